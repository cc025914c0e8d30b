"""Replayed steps per second, on one seeded random walk over the model's allowed events
(Hypothesis-free), the model's successors known in advance as in `safestate conform`:

* step-by-step replay (the replay of the first conformance harness, still used for
  --out and for reporting a mismatch): per step one binding call, observe() as a dict,
  the projection and the comparison in Python;
* batched replay (the adapter's fast_replay -> core.replay_compare, the previous fast
  path): the whole walk in one binding call, compared in C++ against the projections'
  canonical lines, the Python preparation (interning inputs and projections) per call;
* plan replay (conform/replay_plan.py -> core.PlanReplayer, what `safestate conform` runs):
  the walk encoded once as a compact plan (small-int calls, interned expected lines; in
  conform it is cached on disk beside the explored graph), then walked in C++ with no
  Python per step.  The plan's one-time build is reported apart, and with the replay;

and their ratios, in the same run.  --conformance-plan also replays the flagship's whole
conformance plan (the cover of the CI cfg's state graph; built and cached on first use,
which explores the model if its graph is not cached).  Never pass/fail.
    .venv/bin/python bench/bench_conform.py [--steps N] [--conformance-plan] [--json]"""

from __future__ import annotations

import argparse
import json
import random
import time
from pathlib import Path

from safestate.checker.model import load_model
from safestate.conform import replay_plan
from safestate.conform.cli import make_harness
from safestate.conform.traces import ConcreteTrace, Step
from safestate.systems.registry import find

REPO = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--conformance-plan", action="store_true",
                    help="also replay the flagship's whole conformance plan (cached beside the graph)")
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
    t0 = time.perf_counter()
    plan = replay_plan.build(h.adapter, [trace])
    rp = replay_plan.replayer(h.adapter, plan)
    build_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    bad, _ = rp.run(0, plan.traces)
    plan_s = time.perf_counter() - t0
    assert bad == -1, "the plan replay disagrees with the model on the walk"
    out = {"steps": a.steps, "cpp_steps_per_s": round(a.steps / cpp_s),
           "step_by_step_replay_steps_per_s": round(a.steps / lock_s),
           "batched_replay_steps_per_s": round(a.steps / fast_s),
           "plan_replay_steps_per_s": round(a.steps / plan_s),
           "plan_build_seconds": round(build_s, 3),
           "plan_build_and_replay_steps_per_s": round(a.steps / (build_s + plan_s)),
           "batched_over_step_by_step": round(lock_s / fast_s, 1),
           "plan_over_step_by_step": round(lock_s / plan_s, 1),
           "plan_over_batched": round(fast_s / plan_s, 1),
           "step_by_step_with_model_successors_steps_per_s": round(a.steps / (lock_s + model_s))}
    if a.conformance_plan:
        out.update(conformance_plan(h, model))
    print(json.dumps(out) if a.json else "\n".join(f"{k}: {v}" for k, v in out.items()))


def conformance_plan(h, model) -> dict:  # type: ignore[no-untyped-def]
    """The flagship's whole conformance plan (as `safestate conform` replays it) in C++."""
    from safestate.conform import graph as graph_mod
    from safestate.conform.conformance import Options, plan_of
    g = graph_mod.cached_explore(model)
    t0 = time.perf_counter()
    plan = plan_of(h, g, Options())
    load_s = time.perf_counter() - t0
    rp = replay_plan.replayer(h.adapter, plan)
    t0 = time.perf_counter()
    bad, _ = rp.run(0, plan.traces)
    run_s = time.perf_counter() - t0
    assert bad == -1, f"the conformance plan disagrees at trace {bad}"
    steps = plan.steps_in(0, plan.traces)
    return {"conformance_plan_traces": plan.traces, "conformance_plan_steps": steps,
            "conformance_plan_build_or_load_seconds": round(load_s, 3),
            "conformance_plan_replay_seconds": round(run_s, 3),
            "conformance_plan_replay_steps_per_s": round(steps / run_s)}


if __name__ == "__main__":
    main()
