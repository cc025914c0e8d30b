"""Replayed steps per second, on one seeded random walk over the model's allowed events
(Hypothesis-free), the model's successors known in advance as in `safestate conform`:

* step-by-step replay (the replay of the first conformance harness, still used for
  --out and for reporting a mismatch): per step one binding call, observe() as a dict,
  the projection and the comparison in Python;
* batched replay (Adapter.fast_replay -> core.replay_compare): the whole walk in one
  binding call, compared in C++ against the projections' canonical lines, the Python
  preparation (interning inputs and projections) included;

and their ratio, in the same run.  Never pass/fail.
    .venv/bin/python bench/bench_conform.py [--steps N] [--json]"""

from __future__ import annotations

import argparse
import json
import random
import time
from pathlib import Path

from safestate.checker.model import load_model
from safestate.conform.cli import make_harness
from safestate.conform.traces import ConcreteTrace, Step
from safestate.systems.registry import find

REPO = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=20000)
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
    interned: dict = {}  # one Event object per distinct event, as in the state graph
    for _ in range(a.steps):  # model alone, full successor enumeration
        trs = h.stepper.transitions(state)
        event, state = trs[rng.randrange(len(trs))]
        walk.append((interned.setdefault(event, event), state))
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
    trace = ConcreteTrace(model.initial_states()[0], [Step(e, nxt, -1) for e, nxt in walk])
    t0 = time.perf_counter()
    bad, _ = h.adapter.fast_replay([trace], [])
    fast_s = time.perf_counter() - t0
    assert bad == -1, "the batched replay disagrees with the model on the walk"
    out = {"steps": a.steps, "cpp_steps_per_s": round(a.steps / cpp_s),
           "step_by_step_replay_steps_per_s": round(a.steps / lock_s),
           "batched_replay_steps_per_s": round(a.steps / fast_s),
           "batched_over_step_by_step": round(lock_s / fast_s, 1),
           "step_by_step_with_model_successors_steps_per_s": round(a.steps / (lock_s + model_s))}
    print(json.dumps(out) if a.json else "\n".join(f"{k}: {v}" for k, v in out.items()))


if __name__ == "__main__":
    main()
