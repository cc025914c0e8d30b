"""``safestate conform SYSTEM|MODEL.tla [--config CFG] [--json] [--out DIR]
[--hypothesis-steps N] [--input-complete] [--replay FILE] [--graph FILE] [--core-module NAME]``.

SYSTEM is a name from the registry (`safestate systems`); a MODEL.tla path is looked
up in the registry by its model.  The system's adapter (systems/<Name>/adapter.py)
maps the model onto its C++ binding.  Explores the model (or reads `--graph` from
`safestate check --graph`), covers every reachable transition with traces from the
initial states, replays each step through the C++ and compares after every step; then
Hypothesis lockstep testing for `--hypothesis-steps` steps, optionally the
input-complete pass, and the transition-table audit.  `--replay FILE` replays one ITF
trace (e.g. a reproducer written on a mismatch) instead.

Exit codes: 0 conformant (zero mismatches, every transition covered, no table row
missing); 20 the C++ disagrees with the model; 21 no disagreement but the evidence is
incomplete (a transition not covered, a row never taken or a declared-unreachable row
fired); 2 a usage or input error (one line on stderr, no traceback).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from typing import Any

from ..checker.model import Model, load_model
from ..errors import UsageError, run_guarded
from ..systems.registry import System, resolve_system
from . import audit as audit_mod
from . import conformance, graph as graph_mod, itf_io
from .adapter import Adapter
from .binding import ENV as CORE_ENV
from .binding import load_core
from .model_step import ModelStepper
from .replay import Harness

OK = 0
USAGE = 2
MISMATCH = 20
INCOMPLETE = 21


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("model", metavar="SYSTEM|MODEL.tla",
                   help="a registered system (safestate systems) or its .tla module")
    p.add_argument("--config", help="the .cfg file (default: MODEL.cfg beside the module)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.add_argument("--out", metavar="DIR", help="write every trace as ITF under DIR/traces/ and reproducers in DIR")
    p.add_argument("--hypothesis-steps", type=int, metavar="N",
                   help="Hypothesis lockstep testing for at least N steps (default: the system's "
                        "hypothesis_steps in its manifest; 0 skips)")
    p.add_argument("--seed", type=int, help="seed of the Hypothesis run (default: random)")
    p.add_argument("--replay", metavar="FILE", help="replay this ITF trace instead of the whole suite")
    p.add_argument("--graph", metavar="FILE", help="read the state graph written by `safestate check --graph`")
    p.add_argument("--max-len", type=int, default=1000, help="longest trace, in steps (default 1000)")
    p.add_argument("--input-complete", action="store_true",
                   help="also apply every input vector of the adapter's full alphabet from every reachable state")
    p.add_argument("--core-module", help="binding module to drive (default: the system's binding; "
                   "or $SAFESTATE_CORE_MODULE)")


def _progress(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def run(args: argparse.Namespace) -> int:
    return run_guarded(lambda: _run(args), args.model, USAGE)


def make_harness(system: System, model: Model, core_module: str | None = None) -> Harness:
    """The model stepper and the system's adapter over its binding (or `core_module`)."""
    if system.conformance is None:
        raise UsageError(f"{system.manifest}: system {system.name} has no [conformance] section")
    core = load_core(core_module or os.environ.get(CORE_ENV) or system.conformance.binding)
    stepper = ModelStepper(model)
    adapter: Adapter = system.load_adapter_class()(core, stepper)
    return Harness(stepper, adapter)


def _run(args: argparse.Namespace) -> int:
    start = time.monotonic()
    for opt in ("max_len", "hypothesis_steps"):
        v = getattr(args, opt)
        if v is not None and v < (1 if opt == "max_len" else 0):
            raise UsageError(f"--{opt.replace('_', '-')} must be {'positive' if opt == 'max_len' else '>= 0'}, got {v}")
    for opt in ("graph", "replay", "config"):
        v = getattr(args, opt)
        if v is not None and not os.path.isfile(v):
            raise UsageError(f"{v}: --{opt} file does not exist")
    system, model_path, cfg = resolve_system(args.model, args.config)
    if system.conformance is None:
        raise UsageError(f"{system.manifest}: system {system.name} has no [conformance] section (no C++ binding "
                         f"and adapter): nothing to check its model against; `safestate systems --with-conformance` "
                         f"lists the systems that have one")
    conformance.check_writable(args.out)
    model = load_model(model_path, cfg)
    harness = make_harness(system, model, args.core_module)
    _progress(f"conform: the model's steps computed by {harness.stepper.engine_note}")
    core = harness.core
    if args.replay:
        return _replay_file(args, model, harness)
    _progress("conform: exploring the model" if not args.graph else f"conform: reading {args.graph}")
    g = graph_mod.load(model, args.graph) if args.graph else graph_mod.cached_explore(model, progress=_progress)
    opts = conformance.Options(out=args.out, reproducer_dir=args.out or ".", max_len=args.max_len,
                               progress=_progress)
    res = conformance.run(model, core, g, harness, opts)
    hyp_steps, hyp_failure = 0, None
    want_steps = args.hypothesis_steps if args.hypothesis_steps is not None else \
        (system.conformance.hypothesis_steps if system.conformance else 0)
    if want_steps > 0:
        from .lockstep import run_lockstep
        hyp_steps, hyp_failure = run_lockstep(harness, model, want_steps, progress=_progress, seed=args.seed)
    complete = None
    if args.input_complete:
        from .input_complete import run_input_complete
        complete = run_input_complete(harness, g, progress=_progress)
    aud = audit_mod.audit(harness.adapter, harness.stats.rows)
    mismatches = len(res.found) + (1 if hyp_failure else 0) + (1 if complete and complete.mismatch else 0)
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
        "system": system.name,
        "input_complete": complete.summary() if complete else None,
        "measured": harness.adapter.measurements(),
        "replay_seconds": round(res.replay_seconds, 3),     # in batched binding calls
        "model_seconds": round(res.model_seconds, 3),       # materialising the model's traces
        "seconds": round(time.monotonic() - start, 3),
    }
    complete_ok = res.transitions_covered == res.transitions_total and aud.ok
    if args.json:
        print(json.dumps(summary))
    else:
        _print_text(summary, res, hyp_failure)
        if complete:
            print(complete.render())
    return MISMATCH if mismatches else OK if complete_ok else INCOMPLETE


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
    for key, value in s["measured"].items():
        print(f"measured: {key}: {value}")
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
    return MISMATCH if mm else OK
