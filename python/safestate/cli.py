"""The ``safestate`` console script.

Each subcommand lives in its own module exposing ``add_arguments(parser)`` and
``run(args) -> int``; register it in `SUBCOMMANDS`.  Wherever a subcommand takes a
model path, a system name from the registry (`safestate systems`) works too.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys

from . import __version__
from .errors import SafestateError, closed_stdout_exit, one_line

# name -> (module, one-line help).
SUBCOMMANDS: dict[str, tuple[str, str]] = {
    "systems": ("safestate.systems.cli", "list the registered systems (systems/*/system.toml) and their parts"),
    "check": ("safestate.checker.cli", "model-check a TLA+ specification (TLC-equivalent)"),
    "prove": ("safestate.prove.cli", "prove invariants with z3 (BMC, k-induction, PDR)"),
    "conform": ("safestate.conform.cli", "check the C++ implementation against the model"),
    "mutate": ("safestate.mutate.cli", "mutation score: do the model's properties pin down its behaviour?"),
    "evidence": ("safestate.evidence.cli", "build (or --verify) the certification evidence package"),
    "demo": ("safestate.demo_cli", "run a system's C++ demo scenario (saf: Safety service over UDP)"),
    "panel": ("safestate.panel.cli", "the operator panel: cell simulator + C++ core + web bridge, prints the URL"),
    "saf": ("safestate.saf_service.cli", "the Safety service as processes: serve, client and subsystem simulators"),
}

DESCRIPTION = """\
safestate: formally verified safety state machines.  The pipeline, per system
(systems/<Name>/system.toml): model (TLA+) -> check -> prove -> conform (C++).

  safestate systems                       the registered systems and their parts
  safestate check   SYSTEM|MODEL.tla      model checking, TLC's verdicts and counts
  safestate prove   SYSTEM|MODEL.tla      unbounded proofs of every invariant (z3)
  safestate conform SYSTEM|MODEL.tla      the C++ against the model (replay, Hypothesis)
  safestate mutate  SYSTEM|MODEL.tla      mutation score of the model's properties
  safestate evidence [--out DIR]          the evidence package: matrix, diagrams, manifest
"""

EXIT_CODES = """\
exit codes (every subcommand):
  0     success: no error found / every invariant proved / conformant
  1     check --tlc: TLC disagrees; prove: an invariant neither proved nor violated;
        evidence: a step failed (the package is still written) / --verify found a difference
  2     usage or input error (bad argument, missing or malformed file, unknown system
        or binding module, unwritable output path): one line on stderr, no traceback
  3     check --tlc: TLC could not be run (TLA2TOOLS_JAR not a TLC jar, java failed);
        mutate: the mutation score is below --min-score
  10/11/13/14  check: assumption / deadlock / liveness / Assert failure (TLC's codes)
  12    an invariant is violated (check: TLC's code; prove: a counterexample)
  13    prove: an invariant is ill-defined (a reachable evaluation TLA+ leaves undefined,
        named with file:line:col and a trace)
  20    conform: the C++ disagrees with the model (a mismatch)
  21    conform: no mismatch, but the evidence is incomplete (a transition not covered,
        a table row never taken or a declared-unreachable row fired)
  74    check: stdout or the --itf/--graph file could not be written (full disk);
        the verdict is printed first
  75/76 check: evaluation error in the next-state relation / an invariant
  124   evidence --verify: no difference, but a re-run check reached --check-timeout
  130   interrupted (check --json: one object, "result": "interrupted", counts so far)
  143   terminated (SIGTERM)
  150/151  check: TLA+ module / .cfg error (file:line:col on stderr)
  153   check: memory limit reached
  255   check: internal error, or where TLC exits with 255 (a malformed .cfg, a number
        beyond TLC's 32-bit integers)
"""


def _resolve_system_names(args: argparse.Namespace) -> None:
    """A registered system name in place of MODEL.tla: its model and CI cfg."""
    model = getattr(args, "model", None)
    if args.command in ("check", "prove") and model and not os.path.exists(model) and not model.endswith(".tla"):
        from .systems.registry import find

        system = find(model)
        if system is not None:
            args.model = str(system.model)
            if getattr(args, "config", None) is None:
                args.config = str(system.ci_config)
            if args.command == "prove" and getattr(args, "proofs", None) is None and system.proofs:
                args.proofs = str(system.proofs)


def _chosen_command(argv: list[str]) -> str | None:
    """The subcommand the arguments name (the first one not an option), if any: only its
    module is imported, which halves the start-up of a `safestate check`."""
    first = next((a for a in argv if not a.startswith("-")), None)
    return first if first in SUBCOMMANDS else None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="safestate", description=DESCRIPTION, epilog=EXIT_CODES,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"safestate {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    chosen = _chosen_command(sys.argv[1:] if argv is None else argv)
    for name, (module_name, help_text) in SUBCOMMANDS.items():
        if name != chosen:  # listed by --help; its module (z3, the evidence builder...) not imported
            sub.add_parser(name, help=help_text)
            continue
        module = importlib.import_module(module_name)
        p = sub.add_parser(name, help=help_text, description=module.__doc__, epilog=EXIT_CODES,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        module.add_arguments(p)
        p.set_defaults(run=module.run)
    args = parser.parse_args(argv)
    try:
        _resolve_system_names(args)
    except SafestateError as e:  # a malformed manifest of the system named
        print(f"error: {one_line(e)}", file=sys.stderr)
        return 2
    try:
        return int(args.run(args))
    except BrokenPipeError:  # a subcommand without its own guard; `... | head` is not an error
        return closed_stdout_exit()


if __name__ == "__main__":
    sys.exit(main())
