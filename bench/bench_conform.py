"""Replayed steps per second: through the C++ alone, and in lockstep with the model
(Hypothesis-free; a seeded random walk over the model's allowed events).  Never
pass/fail.   .venv/bin/python bench/bench_conform.py [--steps N] [--json]"""

from __future__ import annotations

import argparse
import json
import random
import time
from pathlib import Path

from safestate.checker.model import load_model
from safestate.conform.cli import make_harness
from safestate.systems.registry import find

REPO = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    system = find("SystemStateManager", REPO / "systems")
    assert system is not None
    model = load_model(str(system.model), str(system.ci_config))
    h = make_harness(system, model)
    rng = random.Random(1)
    state = model.initial_states()[0]
    walk = []
    t0 = time.perf_counter()
    for _ in range(a.steps):  # model alone, full successor enumeration
        trs = h.stepper.transitions(state)
        event, state = trs[rng.randrange(len(trs))]
        walk.append((event, state))
    model_s = time.perf_counter() - t0
    m = h.adapter.new_sut()
    state = model.initial_states()[0]
    t0 = time.perf_counter()
    for event, nxt in walk:  # C++ alone, through the adapter (inputs mapped, observe())
        h.adapter.apply(m, event, state)
        h.adapter.observe(m)
        state = nxt
    cpp_s = time.perf_counter() - t0
    ls = h.lockstep(model.initial_states()[0])
    t0 = time.perf_counter()
    for event, nxt in walk:  # lockstep: C++ + projection + rows, successor known
        ls.step(event, nxt, check_rows=True)
    lock_s = time.perf_counter() - t0
    out = {"steps": a.steps, "cpp_steps_per_s": round(a.steps / cpp_s),
           "lockstep_steps_per_s_successor_known": round(a.steps / lock_s),
           "lockstep_steps_per_s_with_model_successors": round(a.steps / (lock_s + model_s))}
    print(json.dumps(out) if a.json else "\n".join(f"{k}: {v}" for k, v in out.items()))


if __name__ == "__main__":
    main()
