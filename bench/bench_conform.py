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
from safestate.conform.binding import load_core
from safestate.conform.events import CYCLE
from safestate.conform.inputs import submit_args
from safestate.conform.model_step import ModelStepper
from safestate.conform.replay import Harness

MODEL = Path(__file__).resolve().parents[1] / "models" / "SystemStateManager.tla"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    model = load_model(str(MODEL))
    h = Harness(ModelStepper(model), load_core())
    rng = random.Random(1)
    state = model.initial_states()[0]
    walk = []
    t0 = time.perf_counter()
    for _ in range(a.steps):  # model alone, full successor enumeration
        trs = h.stepper.transitions(state)
        event, state = trs[rng.randrange(len(trs))]
        walk.append((event, state))
    model_s = time.perf_counter() - t0
    m = h.core.Manager(h.config)
    t0 = time.perf_counter()
    for event, _ in walk:  # C++ alone, through the binding (inputs mapped, observe())
        if event.action == CYCLE:
            m.cycle(h.mapper.raw(event.record(), event.param()))
        else:
            m.submit(*submit_args(event.record()))
        m.observe()
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
