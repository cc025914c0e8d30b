"""``safestate conform MODEL.tla [--config CFG] [--json] [--out DIR]
[--hypothesis-steps N] [--replay FILE] [--graph FILE] [--core-module NAME]``.

Explores the model (or reads `--graph` from `safestate check --graph`), covers every
reachable transition with traces from the initial states, replays each step through
the C++ binding and compares after every step; then Hypothesis lockstep testing for
`--hypothesis-steps` steps, and the transition-table audit.  Exit 0 only with zero
mismatches, full transition coverage and no missing row.  `--replay FILE` replays
one ITF trace (e.g. a reproducer written on a mismatch) instead.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from typing import Any

from ..checker.model import load_model
from . import audit as audit_mod
from . import conformance, graph as graph_mod, itf_io
from .binding import load_core
from .model_step import ModelStepper
from .replay import Harness


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("model", help="the .tla module (models/SystemStateManager.tla)")
    p.add_argument("--config", help="the .cfg file (default: MODEL.cfg beside the module)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.add_argument("--out", metavar="DIR", help="write every trace as ITF under DIR/traces/ and reproducers in DIR")
    p.add_argument("--hypothesis-steps", type=int, default=0, metavar="N",
                   help="also run Hypothesis lockstep testing for at least N steps (default 0)")
    p.add_argument("--replay", metavar="FILE", help="replay this ITF trace instead of the whole suite")
    p.add_argument("--graph", metavar="FILE", help="read the state graph written by `safestate check --graph`")
    p.add_argument("--max-len", type=int, default=1000, help="longest trace, in steps (default 1000)")
    p.add_argument("--core-module", help="binding module to drive (default safestate._core; "
                   "or $SAFESTATE_CORE_MODULE)")


def _progress(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def run(args: argparse.Namespace) -> int:
    start = time.monotonic()
    model = load_model(args.model, args.config)
    core = load_core(args.core_module)
    harness = Harness(ModelStepper(model), core)
    if args.replay:
        return _replay_file(args, model, harness)
    _progress("conform: exploring the model" if not args.graph else f"conform: reading {args.graph}")
    g = graph_mod.load(model, args.graph) if args.graph else graph_mod.explore(model, progress=_progress)
    opts = conformance.Options(out=args.out, reproducer_dir=args.out or ".", max_len=args.max_len,
                               progress=_progress)
    res = conformance.run(model, core, g, harness, opts)
    hyp_steps, hyp_failure = 0, None
    if args.hypothesis_steps > 0:
        from .lockstep import run_lockstep
        hyp_steps, hyp_failure = run_lockstep(harness, model, args.hypothesis_steps, progress=_progress)
    aud = audit_mod.audit(core, harness.stats.rows)
    mismatches = len(res.found) + (1 if hyp_failure else 0)
    summary: dict[str, Any] = {
        "transitions_total": res.transitions_total,
        "transitions_covered": res.transitions_covered,
        "traces": res.traces,
        "steps": res.steps,
        "mismatches": mismatches,
        "hypothesis_steps": hyp_steps,
        "rows_taken": aud.rows_taken,
        "rows_unreachable": aud.rows_unreachable,
        "rows_missing": aud.rows_missing,
        "rows_unreachable_fired": aud.unreachable_fired,
        "row_checks": harness.stats.row_checks,
        "reproducers": [f.reproducer for f in res.found],
        "first_mismatch": res.found[0].mismatch.render() if res.found else hyp_failure,
        "traces_written": res.traces_written,
        "core_module": core.__name__,
        "seconds": round(time.monotonic() - start, 3),
    }
    ok = mismatches == 0 and res.transitions_covered == res.transitions_total and aud.ok
    if args.json:
        print(json.dumps(summary))
    else:
        _print_text(summary, res, hyp_failure)
    return 0 if ok else 1


def _print_text(s: dict[str, Any], res: conformance.ConformResult, hyp_failure: str | None) -> None:
    for f in res.found[:1]:
        print(f.mismatch.render())
        print(f"reproducer ({f.reproducer_steps} steps): {f.reproducer}")
    if hyp_failure:
        print(hyp_failure)
    print(f"transitions covered: {s['transitions_covered']}/{s['transitions_total']}")
    print(f"traces: {s['traces']}, steps replayed: {s['steps']}, mismatches: {s['mismatches']}")
    print(f"hypothesis steps: {s['hypothesis_steps']}")
    print(f"rows taken: {len(s['rows_taken'])}, unreachable by construction (never fired): "
          f"{' '.join(s['rows_unreachable']) or '-'}, missing: {' '.join(s['rows_missing']) or '-'}")
    if s["rows_unreachable_fired"]:
        print(f"rows declared unreachable but fired: {' '.join(s['rows_unreachable_fired'])}")
    print(f"seconds: {s['seconds']}")


def _replay_file(args: argparse.Namespace, model: Any, harness: Harness) -> int:
    """Replay one ITF trace; the model recomputes every state from the first."""
    ct = itf_io.read(args.replay, model)
    recorded = [st.state for st in ct.steps]
    for st in ct.steps:
        st.state = None  # type: ignore[assignment]
    state = ct.initial
    for st in ct.steps:
        st.state = harness.stepper.successor(state, st.event)
        state = st.state
    differs = sum(1 for a, b in zip(recorded, (st.state for st in ct.steps)) if a != b)
    mm, n = conformance.replay_trace(harness, ct)
    out = {"file": args.replay, "steps": n, "mismatches": 1 if mm else 0,
           "recorded_states_differing_from_model": differs}
    if args.json:
        out["first_mismatch"] = mm.render() if mm else None
        print(json.dumps(out))
    else:
        if mm:
            print(mm.render())
        print(f"replayed {n}/{len(ct.steps)} steps of {args.replay}: {'MISMATCH' if mm else 'no mismatch'}")
        if differs:
            print(f"note: {differs} recorded state(s) differ from the model's successors")
    return 1 if mm else 0
