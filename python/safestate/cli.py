"""The ``safestate`` console script.

Each subcommand lives in its own module exposing ``add_arguments(parser)`` and
``run(args) -> int``; register it in `SUBCOMMANDS`.
"""

from __future__ import annotations

import argparse
import importlib
import sys

# name -> (module, one-line help).
SUBCOMMANDS: dict[str, tuple[str, str]] = {
    "check": ("safestate.checker.cli", "model-check a TLA+ specification (TLC-equivalent)"),
    "prove": ("safestate.prove.cli", "prove invariants with z3 (BMC, k-induction, PDR)"),
    "conform": ("safestate.conform.cli", "check the C++ implementation against the model"),
    "demo": ("safestate.demo_cli", "run a system's C++ demo scenario (saf: Safety service over UDP)"),
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="safestate", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    for name, (module_name, help_text) in SUBCOMMANDS.items():
        module = importlib.import_module(module_name)
        p = sub.add_parser(name, help=help_text)
        module.add_arguments(p)
        p.set_defaults(run=module.run)
    args = parser.parse_args(argv)
    return int(args.run(args))


if __name__ == "__main__":
    sys.exit(main())
