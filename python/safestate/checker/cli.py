"""``safestate check MODEL.tla [--config CFG] [--workers N|auto] [--engine python|native|auto]
[--json] [--itf FILE] [--graph FILE] [--tlc] [--max-memory MB]``.

Text output follows TLC's summary lines; ``--json`` prints one object instead.
Exit codes are TLC's (see `exit_codes.py` and docs/tla-subset.md).  Every failure
is reported as a one- or two-line message with file:line:column; a Python
traceback never reaches the user (an internal error prints "internal error").
"""

from __future__ import annotations

import argparse
import io
import json
import os
import signal
import subprocess
import sys
import threading
import time
from typing import Any, Callable, TextIO

from ..errors import UsageError, check_writable_file, closed_stdout_exit, one_line, whole_number
from ..tla.errors import TlaError
from . import exit_codes
from .explore import CheckResult, explore_states, print_progress
from .itf import trace_to_itf
from .model import Model, default_config_path, load_model


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("model", help="the .tla module to check")
    p.add_argument("--config", help="the .cfg file (default: MODEL.cfg beside the module)")
    p.add_argument("--workers", default=None,
                   help="workers (processes of the Python engine, threads of the native one, shards with --ray): "
                   "a number or 'auto' (default 1; with --ray 2)")
    p.add_argument("--ray", metavar="ADDRESS", help="shard the search over Ray actors, each running the Python "
                   "engine on its shard: 'local' starts a cluster on this machine for the run, else the address "
                   "of a running cluster (`ray start --head`); docs/distributed.md")
    p.add_argument("--checkpoint", metavar="DIR", help="with --ray: the shards keep a checkpoint in DIR (a folder "
                   "every machine reaches) at the end of a level, at most every --checkpoint-every seconds; "
                   "failed workers are replaced from it")
    p.add_argument("--checkpoint-every", type=whole_number(0), default=60, metavar="S",
                   help="seconds between checkpoints (default 60; 0: every level)")
    p.add_argument("--resume", metavar="DIR", help="with --ray: go on from the last checkpoint in DIR (the same "
                   "model, cfg and --workers), and keep checkpointing there")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.add_argument("--itf", metavar="FILE", help="write the counterexample as an ITF JSON trace")
    p.add_argument("--graph", metavar="FILE", help="write the whole reachable state graph as JSON")
    p.add_argument("--tlc", action="store_true", help="also run TLC ($TLA2TOOLS_JAR) and compare")
    p.add_argument("--engine", choices=("python", "native", "auto"), default="auto",
                   help="auto (default: the C++ core where it applies, else the Python engine, said in one "
                   "line on stderr), native (the core only: refused with file:line:col outside it) or python "
                   "(the reference evaluator)")
    p.add_argument("--max-memory", type=whole_number(1), metavar="MB", help="stop with an error above this resident "
                   "memory (default 70%% of RAM)")


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity, which a container or
    `taskset` narrows), not the machine's."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def _ray_workers(text: str | None) -> int:
    """--workers with --ray: shards, one per CPU of the cluster, not capped by this machine's cores."""
    if text is None:
        return 2
    if not text.isdigit() or int(text) < 1:
        raise UsageError(f"--workers with --ray expects a number of shards (at least 1), not {text!r}")
    return int(text)


def _workers(text: str) -> int:
    """--workers as a number of processes: more than the cores available only slows the
    search down (and a thousand forks never finish), so it is capped, with a warning."""
    cores = available_cores()
    if text == "auto":
        return cores
    try:
        n = int(text)
    except ValueError:
        raise UsageError(f"--workers expects a number or 'auto', not {text!r}") from None
    if n < 1:
        raise UsageError(f"--workers must be at least 1, not {n}")
    if n > cores:
        print(f"safestate check: --workers {n} is more than the {cores} core{'s' if cores > 1 else ''} available; "
              f"using {cores}", file=sys.stderr, flush=True)
        return cores
    return n


class Terminated(BaseException):
    """SIGTERM, turned into an exception so that every `finally` runs (the parallel
    search's shared-memory folder is removed, its workers are stopped)."""


def _on_sigterm(signum: int, frame: object) -> None:
    raise Terminated()


def run(args: argparse.Namespace) -> int:
    start = time.monotonic()
    try:
        for option in ("itf", "graph"):
            if getattr(args, option):
                check_writable_file(getattr(args, option), f"--{option}")
        args.workers = _ray_workers(args.workers) if args.ray else _workers(args.workers or "1")
        if (args.checkpoint or args.resume) and not args.ray:
            raise UsageError("--checkpoint and --resume are for the search on Ray: give --ray too")
        if args.checkpoint and args.resume:
            raise UsageError("--resume DIR keeps checkpointing in DIR: give --checkpoint or --resume, not both")
        if args.checkpoint:
            try:
                os.makedirs(args.checkpoint, exist_ok=True)
            except OSError as e:
                raise UsageError(f"--checkpoint {args.checkpoint}: cannot make the folder ({e.strerror})") from None
        if args.ray and args.engine == "native":
            raise UsageError("--ray runs the Python engine on each shard; --engine native is one process only")
    except UsageError as e:
        return _usage_error(args, e)
    previous = signal.getsignal(signal.SIGTERM)
    in_main_thread = threading.current_thread() is threading.main_thread()
    if in_main_thread:
        signal.signal(signal.SIGTERM, _on_sigterm)
    try:
        return _guarded(args, start)
    finally:
        if in_main_thread:
            signal.signal(signal.SIGTERM, previous)


def _guarded(args: argparse.Namespace, start: float) -> int:
    try:
        return _run(args, start)
    except UsageError as e:
        return _usage_error(args, e)
    except TlaError as e:
        return _fail(args, e, start)
    except KeyboardInterrupt:
        return _interrupted(args, start, "interrupted", exit_codes.INTERRUPTED)
    except Terminated:
        return _interrupted(args, start, "terminated", exit_codes.TERMINATED)
    except BrokenPipeError:
        return closed_stdout_exit()
    except OutputError as e:
        print(f"error: {e}", file=sys.stderr)
        return exit_codes.OUTPUT_FAILED
    except Exception as e:  # noqa: BLE001 - the boundary: never show a traceback
        msg = f"internal error: {type(e).__name__}: {e}"
        print(msg, file=sys.stderr)
        if args.json:
            _emit(json.dumps({"result": "error", "error": {"message": msg, "file": None, "line": None,
                                                           "column": None}}), quiet=True)
        return exit_codes.ERROR


class OutputError(Exception):
    """stdout or an output file (--itf, --graph) could not be written (a full disk)."""


def _emit(text: str, quiet: bool = False) -> None:
    """`text` and a newline on stdout, flushed now so that a full disk is reported here
    and not as a traceback at the interpreter's exit."""
    try:
        sys.stdout.write(text + "\n")
        sys.stdout.flush()
    except BrokenPipeError:
        raise
    except OSError as e:
        _drop_stdout()
        if not quiet:
            raise OutputError(f"cannot write the result to stdout: {e.strerror or e}") from None


def _drop_stdout() -> None:
    """What stdout still buffers is lost: point it at /dev/null so that the final flush
    at exit cannot raise again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass


def _interrupted(args: argparse.Namespace, start: float, what: str, code: int) -> int:
    """Ctrl-C (or SIGTERM): how far the search got, as one JSON object with --json."""
    print(what, file=sys.stderr)
    if args.json:
        from .explore import counts_so_far
        doc: dict[str, Any] = {"result": what, **counts_so_far(), "violated": None, "trace": None,
                               "seconds": round(time.monotonic() - start, 3)}
        try:
            _emit(json.dumps(doc))
        except OutputError as e:
            print(f"error: {e}", file=sys.stderr)
    return code


def _usage_error(args: argparse.Namespace, e: UsageError) -> int:
    """An unusable argument: exit code 2 (`safestate --help`), one line, before the search."""
    print(f"error: {one_line(e)}", file=sys.stderr)
    if args.json:
        _emit(json.dumps({"result": "error", "error": {"message": str(e), "kind": "usage", "file": None,
                                                       "line": None, "column": None}}), quiet=True)
    return exit_codes.USAGE


def _fail(args: argparse.Namespace, e: TlaError, start: float) -> int:
    code = exit_codes.BY_KIND.get(e.kind, exit_codes.ERROR)
    where = f"{e.loc}: " if e.loc else ""
    print(f"{where}error: {e.message}", file=sys.stderr)
    if args.json:
        _emit(json.dumps(_json_error(e, time.monotonic() - start)))
    return code


def _json_error(e: TlaError, seconds: float, counts: CheckResult | None = None) -> dict:
    return {
        "result": "error",
        "distinct_states": counts.distinct_states if counts else 0,
        "states_generated": counts.states_generated if counts else 0,
        "depth": counts.depth if counts else 0,
        "violated": None, "trace": None, "seconds": round(seconds, 3),
        "error": {"message": e.message, "kind": e.kind, "file": e.loc.file if e.loc else None,
                  "line": e.loc.line if e.loc and e.loc.line > 0 else None,
                  "column": e.loc.column if e.loc and e.loc.line > 0 else None},
    }


def _run(args: argparse.Namespace, start: float) -> int:
    from .explore import RUNNING
    RUNNING.clear()  # an interrupted search reports its own counts, not an earlier one's
    workers = args.workers
    model = load_model(args.model, args.config)
    progress = None if args.json else print_progress
    if args.ray:
        from ..distributed.ray_search import RayTarget
        folder = args.resume or args.checkpoint
        target = RayTarget(args.ray, args.model, args.config or default_config_path(args.model), folder,
                           float(args.checkpoint_every), bool(args.resume))
        result = explore_states(model, workers=workers, graph=bool(args.graph), max_memory_mb=args.max_memory,
                                progress=progress, ray=target)
    elif args.engine == "python":
        result = explore_states(model, workers=workers, graph=bool(args.graph), max_memory_mb=args.max_memory,
                                progress=progress)
    else:
        from .native.engine_choice import check
        result = check(model, args.engine, workers=workers, graph=bool(args.graph), max_memory_mb=args.max_memory,
                       progress=progress)
    itf = _itf(model, result) if result.trace else None
    summary = _summary(model, result, itf, time.monotonic() - start)
    code = exit_codes.BY_RESULT.get(result.result)
    if code is None:
        assert result.error is not None
        code = exit_codes.BY_KIND.get(result.error.kind, exit_codes.ERROR)
    # The verdict first: an output file that cannot be written (a full disk) must not
    # take the verdict with it.
    if args.json:
        _emit(json.dumps(summary))
    else:
        from .report import write_result
        out = io.StringIO()
        write_result(out, model, result)
        _emit(out.getvalue().rstrip("\n"))
    failed = _write_outputs(args, model, result, itf)
    if args.tlc:
        code = _second_opinion(args, summary, code)
    return exit_codes.OUTPUT_FAILED if failed else code


def _write_outputs(args: argparse.Namespace, model: Model, result: CheckResult, itf: dict | None) -> bool:
    """Write --itf and --graph; a failure is one line on stderr (True), after the verdict."""
    failed = False
    if args.itf:
        if itf is None:
            print(f"no counterexample: {args.itf} not written", file=sys.stderr)
        else:
            failed |= not _write_file(args.itf, "--itf", lambda f: _dump(itf, f, indent=1))
    if args.graph and result.states is not None:
        from .graph import graph_json
        doc = graph_json(model, result)
        failed |= not _write_file(args.graph, "--graph",
                                  lambda f: _dump(doc, f, separators=(",", ":")))
    return failed


def _dump(doc: object, f: TextIO, **how: Any) -> None:
    json.dump(doc, f, **how)
    f.write("\n")


def _write_file(path: str, option: str, write: Callable[[TextIO], object]) -> bool:
    try:
        with open(path, "w", encoding="utf-8") as f:
            write(f)
        return True
    except OSError as e:
        print(f"error: {path}: cannot write the {option} file ({e.strerror or e}); the verdict above stands",
              file=sys.stderr)
        return False


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
        failure = _json_error(r.error, seconds, r)
        failure["trace"] = itf
        return failure
    out: dict[str, Any] = {
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
    names: list[Any] = r.violated_properties or ([r.violated] if violated and r.violated else [])
    return {"names": list(model.properties), "result": verdict, "violated": names, "lasso": lasso}


def _second_opinion(args: argparse.Namespace, summary: dict, code: int) -> int:
    from .tlc import compare, run_tlc, tlc_jar
    jar = tlc_jar()
    if jar is None:
        print("TLC second opinion skipped: TLA2TOOLS_JAR is not set to an existing jar.", file=sys.stderr)
        return code
    why = _not_a_tlc_jar(jar)
    if why:
        print(f"error: TLC second opinion not run: TLA2TOOLS_JAR={jar} {why}", file=sys.stderr)
        return exit_codes.SECOND_OPINION_FAILED
    cfg = args.config or default_config_path(args.model)
    try:
        tlc = run_tlc(jar, args.model, cfg)
    except (OSError, RuntimeError, subprocess.SubprocessError) as e:
        print(f"error: TLC second opinion failed to run: {e}", file=sys.stderr)
        return exit_codes.SECOND_OPINION_FAILED
    if tlc.exit_code not in TLC_EXIT_CODES:
        # java's own failure (no JVM, a jar without TLC): TLC never gave a verdict.
        print(f"error: TLC second opinion failed to run: java exited with {tlc.exit_code} and no TLC verdict",
              file=sys.stderr)
        return exit_codes.SECOND_OPINION_FAILED
    diffs = compare(summary, tlc)
    if diffs:
        print("TLC second opinion DISAGREES: " + "; ".join(diffs), file=sys.stderr)
        return exit_codes.SECOND_OPINION_DISAGREES
    print(f"TLC second opinion agrees ({tlc.result}, {tlc.distinct_states} distinct states, "
          f"{tlc.states_generated} generated, depth {tlc.depth}).", file=sys.stderr)
    return code


# Every exit status TLC itself gives (tlc2.output.EC.ExitStatus).
TLC_EXIT_CODES = frozenset({0, 10, 11, 12, 13, 14, 75, 76, 77, 150, 151, 152, 153, 255})


def _not_a_tlc_jar(jar: str) -> str | None:
    """Why `jar` cannot be TLC (None when it holds tlc2/TLC.class)."""
    import zipfile
    try:
        with zipfile.ZipFile(jar) as z:
            z.getinfo("tlc2/TLC.class")
    except KeyError:
        return "has no tlc2/TLC.class: not tla2tools.jar"
    except (OSError, zipfile.BadZipFile) as e:
        return f"is not a jar ({e})"
    return None
