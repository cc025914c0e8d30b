"""`safestate demo SYSTEM`: run a system's C++ demo scenario (built by scripts/setup.sh).

`saf`: the Safety service over UDP on the loopback interface against its simulated peers
(build/cpp/src/saf/saf_demo). `protection`: the fan controller closed around its thermal
plant (build/cpp/src/pro/pro_demo). `ssm`: the SystemStateManager scenario (build/cpp/safestate_demo).
`press`: the hydraulic press accident, flat reference and chain press side by side
(through the binding safestate._press; python/safestate/press_demo.py).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

# system -> the demo executable, relative to the C++ build folder.
DEMOS: dict[str, str] = {
    "saf": "src/saf/saf_demo",
    "ssm": "safestate_demo",
    "protection": "src/pro/pro_demo",
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("system", choices=sorted([*DEMOS, "press"]), help="which system's demo to run")
    parser.add_argument("--build-dir", type=Path,
                        default=Path(os.environ.get("SAFESTATE_BUILD_DIR", REPO / "build" / "cpp")),
                        help="the C++ build folder (default: build/cpp)")
    parser.add_argument("--realtime", action="store_true",
                        help="saf: sleep one CYCLEINTERVAL (50 ms) per cycle")
    parser.add_argument("--events", metavar="E1,E2,...",
                        help="press: the operator input events, comma-separated (default: the flat model's "
                             "counterexample, then two stroke steps)")


def run(args: argparse.Namespace) -> int:
    if args.system == "press":
        from .press_demo import run as press_demo
        return press_demo(args.events.split(",") if args.events else None)
    exe = args.build_dir / DEMOS[args.system]
    if not exe.is_file():
        print(f"safestate demo: {exe} does not exist; build the C++ tree first "
              "(bash scripts/setup.sh)", file=sys.stderr)
        return 2
    extra = ["--realtime"] if args.realtime and args.system == "saf" else []
    return subprocess.run([str(exe), *extra], check=False).returncode
