"""`safestate demo SYSTEM`: run a system's C++ demo scenario (built by scripts/setup.sh).

`saf`: the Safety service over UDP on the loopback interface against its simulated peers
(build/cpp/src/saf/saf_demo). `protection`: the fan controller closed around its thermal
plant (build/cpp/src/pro/pro_demo), its communications slot the Modbus server, with the
operator a Modbus client in another process (python -m safestate.pro_operator, pymodbus)
started once the server listens. `ssm`: the SystemStateManager scenario (build/cpp/safestate_demo).
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
    if args.system == "protection":
        return run_protection(exe)
    extra = ["--realtime"] if args.realtime and args.system == "saf" else []
    return subprocess.run([str(exe), *extra], check=False).returncode


LISTENING = "modbus server listening on 127.0.0.1:"


def run_protection(exe: Path) -> int:
    """pro_demo, and the operator client once its Modbus server listens; pro_demo's exit code."""
    try:
        import pymodbus  # noqa: F401
    except ImportError:
        print("safestate demo protection: the operator client needs pymodbus (pip install pymodbus)",
              file=sys.stderr)
        return 2
    demo = subprocess.Popen([str(exe)], stdout=subprocess.PIPE, text=True, bufsize=1)
    operator: subprocess.Popen[bytes] | None = None
    try:
        assert demo.stdout is not None
        for line in demo.stdout:
            sys.stdout.write(line)
            sys.stdout.flush()
            if operator is None and line.startswith(LISTENING):
                port = line[len(LISTENING):].strip()
                operator = subprocess.Popen([sys.executable, "-m", "safestate.pro_operator", "--port", port],
                                            env={**os.environ, "PYTHONPATH": os.pathsep.join(
                                                [str(REPO / "python"), os.environ.get("PYTHONPATH", "")])})
        code = demo.wait()
    finally:
        if demo.poll() is None:
            demo.kill()
            demo.wait()
        if operator is not None:
            try:
                operator.wait(timeout=15)
            except subprocess.TimeoutExpired:
                operator.kill()
                operator.wait()
    return code
