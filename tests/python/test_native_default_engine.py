"""Issue 32: `safestate check` without --engine runs the native core wherever it
accepts the model (what `--engine native` reports, nothing said about the engine);
elsewhere the Python engine, said in exactly one line on stderr, never silently."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

from conftest import CORPUS, PYTHON_DIR, run_safestate
from native_engines import write_spec


def _report(out: str) -> dict:
    return {k: v for k, v in json.loads(out).items() if k != "seconds"}


def test_check_runs_the_native_core_by_default() -> None:
    spec = str(CORPUS / "NaiveMutex.tla")
    default = run_safestate("check", spec, "--json")
    native = run_safestate("check", spec, "--engine", "native", "--json")
    assert default.returncode == native.returncode == 12
    assert default.stderr == "" and native.stderr == ""
    assert _report(default.stdout) == _report(native.stdout)


def test_check_falls_back_to_the_python_engine_in_one_line_by_default(tmp_path: Path) -> None:
    # A RECURSIVE operator: outside the core's subset.
    tla = write_spec(tmp_path, "Rec", "EXTENDS Naturals\nVARIABLE x\nRECURSIVE F(_)\n"
                     "F(n) == IF n = 0 THEN 0 ELSE F(n - 1)\nInit == x = 0\nNext == x' = F(x) + 1 /\\ x < 3\n",
                     "INIT Init\nNEXT Next\n")
    default = run_safestate("check", tla, "--json")
    python = run_safestate("check", tla, "--engine", "python", "--json")
    assert default.returncode == python.returncode == 0
    lines = default.stderr.strip().splitlines()
    assert len(lines) == 1 and "Rec.tla:7:" in lines[0] and "using the Python engine" in lines[0], default.stderr
    assert python.stderr == ""
    assert _report(default.stdout) == _report(python.stdout)
    text = run_safestate("check", tla)  # the text report: the notice on stderr, the verdict on stdout
    assert text.returncode == 0 and "using the Python engine" in text.stderr
    assert "No error has been found" in text.stdout


def test_ctrl_c_stops_the_native_search_with_its_exit_code(tmp_path: Path) -> None:
    # The core searches without the GIL: Ctrl-C must still stop it (130, TLC's code).
    tla = write_spec(tmp_path, "Endless", "EXTENDS Naturals\nVARIABLES x, y\nInit == x = 0 /\\ y = 0\n"
                     "Next == x' = x + 1 /\\ y' \\in 0..3\n", "INIT Init\nNEXT Next\n")
    env = dict(os.environ, PYTHONPATH=str(PYTHON_DIR) + os.pathsep + os.environ.get("PYTHONPATH", ""))

    def foreground() -> None:  # SIGINT at its default, as from a terminal
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    p = subprocess.Popen([sys.executable, "-m", "safestate.cli", "check", tla], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env, preexec_fn=foreground)
    assert p.stderr is not None
    seen = []
    for line in p.stderr:  # the initial states are done: the core's search is under way
        seen.append(line)
        if "Finished computing initial states" in line:
            break
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=120)
    err = "".join(seen) + err
    assert p.returncode == 130, err
    assert "interrupted" in err and "Traceback" not in err and "Python engine" not in err
