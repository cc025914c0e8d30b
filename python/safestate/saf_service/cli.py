"""`safestate saf`: the Safety service as processes on the configured addresses
(docs/design/safety-service.md §14, §15).

  safestate saf serve     --config saf.toml   the service (C++ host: sender binding, replay
                                              window, optional HMAC on Set Estop and on the
                                              subsystem link, the sequence file kept across
                                              restarts, kernel drop count)
  safestate saf client    --config saf.toml   the Safety Client simulator (stdin: set, clear, silent,
                                              replay HEX, quit)
  safestate saf subsystem --config saf.toml   the subsystem simulator (stdin: health X, quit);
                                              EMERGENCY when the service falls silent

Each logs one line per event on stdout (--json: one JSON object per line). SIGTERM or
SIGINT stops a process after the current cycle with exit code 0; a configuration error
(file:line and what was expected), an unusable key file (not mode 0600/0400), a corrupt
or unreadable sequence file (file:line and what was expected) or a port that cannot be
bound is one line on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import sys

from ..errors import SafestateError, whole_number

ROLES = {
    "serve": ("safestate.saf_service.serve", "run the Safety service"),
    "client": ("safestate.saf_service.client", "run the Safety Client simulator"),
    "subsystem": ("safestate.saf_service.subsystem", "run the subsystem simulator"),
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="role", required=True, metavar="ROLE")
    for name, (_, help_text) in ROLES.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        p.add_argument("--config", required=True, help="the configuration file (saf.toml)")
        p.add_argument("--json", action="store_true", help="one JSON object per event line")
        if name == "client":
            p.add_argument("--mode", choices=["set", "clear", "silent"], default="clear",
                           help="what to send from the start (default: clear)")
        if name == "serve":
            p.add_argument("--cycles", type=whole_number(1), default=None,
                           help="stop after this many cycles (default: until SIGTERM)")


def run(args: argparse.Namespace) -> int:
    import importlib

    module = importlib.import_module(ROLES[args.role][0])
    try:
        return int(module.run(args))
    except SafestateError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
