"""`safestate panel`: the operator panel in a browser (issue 16, design §11).

Starts the cell simulator, the SystemStateManager's control thread and the operator link's
bridge (build/cpp/safestate_link) on 127.0.0.1, renders the C++ transition table's state
diagram with Graphviz, writes a fresh control token to a file of mode 0600, and prints the
panel's URL (the token in its fragment). Ctrl-C stops it.
"""

from __future__ import annotations

import argparse
import signal
import sys
from pathlib import Path

from .server import DEFAULT_BUILD, PanelError, PanelServer


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--port", type=int, default=8080, help="TCP port on 127.0.0.1 (0: any free port)")
    parser.add_argument("--build-dir", type=Path, default=DEFAULT_BUILD, help="the C++ build folder")
    parser.add_argument("--token-file", type=Path, default=None,
                        help="use this token file (mode 0600) instead of a fresh one")


def run(args: argparse.Namespace) -> int:
    if not 0 <= args.port <= 65535:
        print(f"safestate panel: --port {args.port}: expected 0..65535", file=sys.stderr)
        return 2
    try:
        with PanelServer(args.build_dir, args.port, args.token_file) as link:
            print(f"safestate panel: {link.panel_url}", flush=True)
            print("(cell simulator + SystemStateManager + operator link; Ctrl-C stops)", flush=True)
            signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
            try:
                return link.process.wait()
            except KeyboardInterrupt:
                return 0
    except PanelError as e:
        print(f"safestate panel: {e}", file=sys.stderr)
        return 2
