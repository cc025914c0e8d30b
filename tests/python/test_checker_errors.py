"""Bad input (tests/tla/errors): a clear message with file:line, a non-zero exit,
never a Python traceback."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from conftest import ERRORS, PYTHON_DIR, load_expected, run_safestate

EXPECTED = load_expected(ERRORS)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_checker_reports_error_with_position(name: str) -> None:
    want = EXPECTED[name]
    p = run_safestate("check", str(ERRORS / f"{name}.tla"))
    out = p.stdout + p.stderr
    assert p.returncode != 0
    assert "Traceback" not in out
    assert "internal error" not in out
    cfg_error = want["kind"] == "cfg"
    file = f"{name}.cfg" if cfg_error else f"{name}.tla"
    assert f"{file}:{want['line']}:" in out, out


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_checker_json_error_has_location(name: str) -> None:
    p = run_safestate("check", str(ERRORS / f"{name}.tla"), "--json")
    got = json.loads(p.stdout)
    assert got["result"] == "error"
    assert got["error"]["line"] == EXPECTED[name]["line"]
    assert got["error"]["file"].endswith((".tla", ".cfg"))


def test_checker_missing_cfg_is_a_clear_error(tla_dir) -> None:
    path = tla_dir("NoCfg", "---- MODULE NoCfg ----\nVARIABLE x\nInit == x = 0\nNext == x' = x\n====\n")
    p = run_safestate("check", str(path))
    assert p.returncode == 151
    assert "NoCfg.cfg" in p.stderr and "not found" in p.stderr


def test_checker_unknown_file_is_a_clear_error(tmp_path) -> None:
    p = run_safestate("check", str(tmp_path / "Missing.tla"))
    assert p.returncode != 0 and "Traceback" not in p.stderr


@pytest.mark.parametrize("name", sorted(n for n, w in EXPECTED.items() if w["kind"] != "unsupported"))
def test_checker_error_exit_code_is_tlc_exit_code(name: str) -> None:
    p = run_safestate("check", str(ERRORS / f"{name}.tla"))
    assert p.returncode == EXPECTED[name]["tlc_exit_code"], p.stdout + p.stderr


def test_checker_output_into_a_closed_pipe_exits_quietly() -> None:
    """`safestate check X | head -1`: the reader is gone; stop like a Unix tool, no
    "internal error" and no traceback."""
    rfd, wfd = os.pipe()
    os.close(rfd)  # the reader has already exited: every write fails with EPIPE
    env = dict(os.environ, PYTHONPATH=str(PYTHON_DIR))
    p = subprocess.run([sys.executable, "-m", "safestate.cli", "check", str(ERRORS / "HeadOfEmpty.tla")],
                       stdout=wfd, stderr=subprocess.PIPE, text=True, env=env, timeout=120)
    os.close(wfd)
    assert p.returncode == 141, p.stderr
    # stderr carries only the progress lines (initial states) and the default engine's one
    # line on checking again with the Python engine (the core leaves TLC's report to it),
    # never an error about the pipe
    notes = [line for line in p.stderr.splitlines() if line.startswith("safestate check: ")]
    assert len(notes) <= 1 and all("checking again with the Python engine" in n for n in notes), p.stderr
    rest = "\n".join(line for line in p.stderr.splitlines() if line not in notes)
    assert "error" not in rest.lower() and "Traceback" not in p.stderr, p.stderr
