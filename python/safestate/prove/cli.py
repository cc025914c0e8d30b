"""Command line: safestate prove MODEL.tla [--config CFG] [--engine bmc|kind|pdr]
[--depth K] [--json] [--invariant NAME ...] [--proofs PLAN.toml] [--cfg-constants]

Exit codes: 0 every requested invariant proved, 12 one violated (as TLC),
13 one ill-defined (an evaluation TLA+ leaves undefined is reached), 1 some unknown
or vacuous, 2 bad input or a spec the checker rejects.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from typing import Any

from ..checker.cfg import parse_config
from ..errors import whole_number
from ..tla.errors import TlaError
from .engines.result import Result
from .plan import ENGINES, find_plan, load_plan
from .render import format_trace, itf, state_lines
from .runner import prove_all
from .system import System, build


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("model", metavar="MODEL.tla", help="the TLA+ module to prove")
    parser.add_argument("--config", metavar="CFG", help="the .cfg (default: MODEL.cfg)")
    parser.add_argument("--engine", choices=ENGINES, help="override the engine of the proof plan")
    parser.add_argument("--depth", type=whole_number(0), metavar="K", help="BMC depth / largest k of k-induction")
    parser.add_argument("--json", action="store_true", help="print the results as JSON on stdout")
    parser.add_argument("--invariant", nargs="+", metavar="NAME", help="prove only these invariants")
    parser.add_argument("--proofs", metavar="PLAN.toml",
                        help="the proof plan (default: proofs/<Model>.toml, when it exists)")
    parser.add_argument("--cfg-constants", nargs="*", metavar="NAME",
                        help="give these constants (all when no name follows) their .cfg value instead of a "
                             "symbolic one")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")


def run(args: argparse.Namespace) -> int:
    t0 = time.monotonic()

    def log(msg: str) -> None:
        if not args.quiet:
            print(f"[prove {time.monotonic() - t0:6.1f}s] {msg}", file=sys.stderr, flush=True)

    try:
        if not os.path.exists(args.model):
            raise TlaError("config", f"cannot read module file {args.model}", None)
        _checker_accepts(args.model, args.config or _default_cfg(args.model))
        plan = load_plan(args.proofs or find_plan(args.model))
        if plan.path:
            log(f"proof plan {plan.path}")
        cfg = args.config
        sys_ = build(args.model, cfg, proofs_module=plan.module, type_invariant=plan.type_invariant,
                     cfg_constants=None if args.cfg_constants is None else set(args.cfg_constants), log=log)
        log(f"translated: {len(sys_.variables)} variables, {len(sys_.cur_leaves)} state terms, "
            f"{len(sys_.trans_aux)} input terms")
        invariants = _invariants(args, plan, cfg or _default_cfg(args.model))
        results = prove_all(sys_, invariants, plan, args.engine, args.depth, log)
    except TlaError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except RecursionError:
        print(f"error: {args.model}: expression nesting too deep to translate", file=sys.stderr)
        return 2
    except Exception as e:  # a bug of ours, not of the model: still no traceback for the user
        print(f"error: internal error of safestate prove ({type(e).__name__}: {e}); please report it with "
              f"the model", file=sys.stderr)
        return 2
    if args.json:
        print(json.dumps(_json(args.model, sys_, results), indent=2))
    else:
        _print(sys_, results)
    if any(r.status == "violated" for r in results):
        return 12
    if any(r.status == "ill-defined" for r in results):
        return 13
    if any(r.status != "proved" for r in results):
        return 1
    return 0


def _checker_accepts(model: str, cfg: str | None) -> None:
    """A spec `safestate check` rejects (an unknown name, a wrong arity, a failing ASSUME...)
    is not provable: what the prover translates lazily must not hide it."""
    if cfg is None:
        return
    from ..checker.model import load_model
    try:
        load_model(model, cfg)
    except TlaError as e:
        raise TlaError(e.kind, f"not provable: the checker rejects the spec: {e.message}", e.loc) from None


def _default_cfg(model: str) -> str | None:
    p = os.path.splitext(model)[0] + ".cfg"
    return p if os.path.exists(p) else None


def _invariants(args: argparse.Namespace, plan, cfg_path: str | None) -> list[str]:
    if args.invariant:
        return list(args.invariant)
    if plan.steps:
        return list(plan.steps)
    if cfg_path:
        names = [e.name for e in parse_config(cfg_path).invariants]
        if names:
            return names
    raise TlaError("config", "no invariant to prove: give --invariant, a proof plan or a .cfg with INVARIANTS",
                   None)


def _json(model: str, sys_: System, results: list[Result]) -> dict[str, Any]:
    out = []
    for r in results:
        out.append({
            "invariant": r.invariant, "status": r.status, "engine": r.engine, "k": r.k,
            "seconds": round(r.seconds, 3),
            "trace": itf(sys_.variables, r.trace, r.params, model, f"counterexample to {r.invariant}")
            if r.trace else None,
            "cti": itf(sys_.variables, r.cti, r.cti_params, model, f"counterexample to induction of {r.invariant}")
            if r.cti else None,
            "note": r.note,
            "obligations": r.obligations,
            "undefined": r.undefined or None,
            "vacuity": r.vacuity,
        })
    return {"model": sys_.module.name, "constants": sys_.constants_report,
            "untracked": sys_.untracked, "results": out}


def _print(sys_: System, results: list[Result]) -> None:
    print(f"Model {sys_.module.name}")
    for n, v in sys_.constants_report.items():
        print(f"  {n}: {v}")
    if sys_.untracked:
        print(f"  not tracked (untyped by TypeOK, never read): {', '.join(sys_.untracked)}")
    for r in results:
        k = f" k={r.k}" if r.k is not None else ""
        wd = f", {r.obligations} well-definedness obligations" if r.obligations else ""
        print(f"{r.invariant}: {r.status} ({r.engine}{k}, {r.seconds:.2f}s{wd}){' - ' + r.note if r.note else ''}")
        if r.undefined:
            print(f"  {r.undefined}")
        if r.trace:
            print(f"{'Trace to the ill-defined evaluation' if r.status == 'ill-defined' else 'Counterexample'} "
                  f"({len(r.trace)} states):")
            print(format_trace(r.trace, r.params))
        if r.cti and len(r.cti) == 1:
            print("A state of the inductive invariant where it fails (not known to be reachable):")
            print(format_trace(r.cti, r.cti_params))
        elif r.cti:
            print("Counterexample to induction (not known to be reachable):")
            if r.cti_params:
                print(format_trace([], r.cti_params))
            print("  state s:")
            print("\n".join("    " + ln for ln in state_lines(r.cti[0])))
            print("  successor s' (variables that differ from s):")
            changed = {v: x for v, x in r.cti[1].items() if r.cti[0].get(v) != x}
            print("\n".join("    " + ln for ln in state_lines(changed)))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="safestate prove", description=__doc__.splitlines()[0])
    add_arguments(parser)
    return run(parser.parse_args(argv))
