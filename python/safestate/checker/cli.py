"""``safestate check MODEL.tla [--config CFG] [--workers N|auto] [--engine python|native|auto]
[--json] [--itf FILE] [--graph FILE] [--tlc] [--max-memory MB]``.

Text output follows TLC's summary lines; ``--json`` prints one object instead.
Exit codes are TLC's (see `exit_codes.py` and docs/tla-subset.md).  Every failure
is reported as a one- or two-line message with file:line:column; a Python
traceback never reaches the user (an internal error prints "internal error").
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from typing import Any

from ..errors import UsageError, check_writable_file, closed_stdout_exit, one_line
from ..tla.errors import TlaError
from . import exit_codes
from .explore import CheckResult, explore_states, print_progress
from .itf import trace_to_itf
from .model import Model, default_config_path, load_model


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("model", help="the .tla module to check")
    p.add_argument("--config", help="the .cfg file (default: MODEL.cfg beside the module)")
    p.add_argument("--workers", default="1",
                   help="workers (processes of the Python engine, threads of the native one): a number or 'auto' (default 1)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.add_argument("--itf", metavar="FILE", help="write the counterexample as an ITF JSON trace")
    p.add_argument("--graph", metavar="FILE", help="write the whole reachable state graph as JSON")
    p.add_argument("--tlc", action="store_true", help="also run TLC ($TLA2TOOLS_JAR) and compare")
    p.add_argument("--engine", choices=("python", "native", "auto"), default="python",
                   help="python (the reference evaluator, default), native (the C++ core: a subset, "
                   "refused with file:line:col outside it) or auto (native where it applies)")
    p.add_argument("--max-memory", type=int, metavar="MB", help="stop with an error above this resident "
                   "memory (default 70%% of RAM)")


def _workers(text: str) -> int:
    if text == "auto":
        return os.cpu_count() or 1
    try:
        n = int(text)
    except ValueError:
        raise TlaError("config", f"--workers expects a number or 'auto', not {text!r}") from None
    if n < 1:
        raise TlaError("config", "--workers must be at least 1")
    return n


def run(args: argparse.Namespace) -> int:
    start = time.monotonic()
    try:
        for option in ("itf", "graph"):
            if getattr(args, option):
                check_writable_file(getattr(args, option), f"--{option}")
    except UsageError as e:
        return _usage_error(args, e)
    try:
        return _run(args, start)
    except TlaError as e:
        return _fail(args, e, start)
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return closed_stdout_exit()
    except Exception as e:  # noqa: BLE001 - the boundary: never show a traceback
        msg = f"internal error: {type(e).__name__}: {e}"
        if args.json:
            print(json.dumps({"result": "error", "error": {"message": msg, "file": None, "line": None,
                                                            "column": None}}))
        else:
            print(msg, file=sys.stderr)
        return exit_codes.ERROR


def _usage_error(args: argparse.Namespace, e: UsageError) -> int:
    """An unusable argument: exit code 2 (`safestate --help`), one line, before the search."""
    if args.json:
        print(json.dumps({"result": "error", "error": {"message": str(e), "kind": "usage", "file": None,
                                                        "line": None, "column": None}}))
    print(f"error: {one_line(e)}", file=sys.stderr)
    return exit_codes.USAGE


def _fail(args: argparse.Namespace, e: TlaError, start: float) -> int:
    code = exit_codes.BY_KIND.get(e.kind, exit_codes.ERROR)
    if args.json:
        print(json.dumps(_json_error(e, time.monotonic() - start)))
    else:
        where = f"{e.loc}: " if e.loc else ""
        print(f"{where}error: {e.message}", file=sys.stderr)
    return code


def _json_error(e: TlaError, seconds: float, counts: CheckResult | None = None) -> dict:
    return {
        "result": "error",
        "distinct_states": counts.distinct_states if counts else 0,
        "states_generated": counts.states_generated if counts else 0,
        "depth": counts.depth if counts else 0,
        "violated": None, "trace": None, "seconds": round(seconds, 3),
        "error": {"message": e.message, "kind": e.kind, "file": e.loc.file if e.loc else None,
                  "line": e.loc.line if e.loc else None, "column": e.loc.column if e.loc else None},
    }


def _run(args: argparse.Namespace, start: float) -> int:
    workers = _workers(args.workers)
    model = load_model(args.model, args.config)
    progress = None if args.json else print_progress
    if args.engine == "python":
        result = explore_states(model, workers=workers, graph=bool(args.graph), max_memory_mb=args.max_memory,
                                progress=progress)
    else:
        from .native.engine_choice import check
        result = check(model, args.engine, workers=workers, graph=bool(args.graph), max_memory_mb=args.max_memory,
                       progress=progress)
    itf = _itf(model, result) if result.trace else None
    if args.itf:
        if itf is None:
            print(f"no counterexample: {args.itf} not written", file=sys.stderr)
        else:
            with open(args.itf, "w", encoding="utf-8") as f:
                json.dump(itf, f, indent=1)
                f.write("\n")
    if args.graph:
        from .graph import write_graph
        if result.states is not None:
            write_graph(args.graph, model, result)
    summary = _summary(model, result, itf, time.monotonic() - start)
    if args.json:
        print(json.dumps(summary))
    else:
        from .report import write_result
        write_result(sys.stdout, model, result)
    code = exit_codes.BY_RESULT.get(result.result)
    if code is None:
        assert result.error is not None
        code = exit_codes.BY_KIND.get(result.error.kind, exit_codes.ERROR)
    if args.tlc:
        return _second_opinion(args, summary, code)
    return code


def _itf(model: Model, result: CheckResult) -> dict:
    assert result.trace is not None
    desc = {"safety failure": f"invariant {result.violated} violated", "deadlock failure": "deadlock",
            "liveness failure": f"temporal property {result.violated} violated (a lasso)",
            "temporal safety failure": f"temporal property {result.violated} violated by every continuation",
            "action property failure": f"action property {result.violated} violated",
            "init property failure": f"property {result.violated} violated by the initial state"}.get(
        result.result, "behaviour up to an evaluation error")
    loop = None
    if result.loop is not None:
        # The state after the last one: trace[loop], or the last one again when it stutters.
        loop = result.loop if result.loop_step is not None else len(result.trace) - 1
    return trace_to_itf(model.variables, [(s.state, s.action, s.params) for s in result.trace],
                        os.path.basename(model.module.file), desc, loop)


def _summary(model: Model, r: CheckResult, itf: dict | None, seconds: float) -> dict[str, Any]:
    if r.result == "error" and r.error is not None:
        out: dict[str, Any] = _json_error(r.error, seconds, r)
        out["trace"] = itf
        return out
    out = {
        "result": r.result, "distinct_states": r.distinct_states, "states_generated": r.states_generated,
        "depth": r.depth, "violated": r.violated, "trace": itf, "seconds": round(seconds, 3),
        "left_on_queue": r.left_on_queue,
    }
    if model.properties:
        out["properties"] = _property_summary(model, r)
    if r.parallel is not None:
        out["parallel"] = r.parallel
    return out


def _property_summary(model: Model, r: CheckResult) -> dict[str, Any]:
    """The PROPERTY result: satisfied, violated (with the lasso's shape) or not
    checked (the safety search stopped first)."""
    violated = r.result in ("liveness failure", "temporal safety failure", "action property failure",
                            "init property failure")
    if violated:
        verdict = "violated"
    elif r.result == "success":
        verdict = "satisfied"
    else:
        verdict = "not checked"
    lasso = None
    if r.loop is not None and r.trace is not None:
        lasso = {"length": len(r.trace), "loop": r.loop, "stuttering": r.loop_step is None}
    names: list[Any] = r.violated_properties or ([r.violated] if violated else [])
    return {"names": list(model.properties), "result": verdict, "violated": names, "lasso": lasso}


def _second_opinion(args: argparse.Namespace, summary: dict, code: int) -> int:
    from .tlc import compare, run_tlc, tlc_jar
    jar = tlc_jar()
    if jar is None:
        print("TLC second opinion skipped: TLA2TOOLS_JAR is not set to an existing jar.", file=sys.stderr)
        return code
    cfg = args.config or default_config_path(args.model)
    try:
        tlc = run_tlc(jar, args.model, cfg)
    except (OSError, RuntimeError) as e:
        print(f"TLC second opinion failed to run: {e}", file=sys.stderr)
        return exit_codes.SECOND_OPINION_DISAGREES
    diffs = compare(summary, tlc)
    if diffs:
        print("TLC second opinion DISAGREES: " + "; ".join(diffs), file=sys.stderr)
        return exit_codes.SECOND_OPINION_DISAGREES
    print(f"TLC second opinion agrees ({tlc.result}, {tlc.distinct_states} distinct states, "
          f"{tlc.states_generated} generated, depth {tlc.depth}).", file=sys.stderr)
    return code
