"""Shared pytest fixtures for the model checker tests (test_checker_*.py)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
PYTHON_DIR = REPO / "python"
if str(PYTHON_DIR) not in sys.path:
    sys.path.insert(0, str(PYTHON_DIR))

CORPUS = REPO / "tests" / "tla" / "corpus"
ERRORS = REPO / "tests" / "tla" / "errors"


def load_expected(folder: Path) -> dict:
    path = folder / "expected.json"
    return json.loads(path.read_text()) if path.exists() else {}


def run_safestate(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """Run the `safestate` CLI in a subprocess (as a user would)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = str(PYTHON_DIR) + os.pathsep + env.get("PYTHONPATH", "")
    return subprocess.run([sys.executable, "-m", "safestate.cli", *args], capture_output=True, text=True,
                          cwd=cwd, env=env, timeout=600)


@pytest.fixture
def tla_dir(tmp_path: Path):
    """Write small modules: tla_dir("Name", tla_text, cfg_text) -> path of Name.tla."""
    def write(name: str, tla: str, cfg: str | None = None) -> Path:
        (tmp_path / f"{name}.tla").write_text(tla)
        if cfg is not None:
            (tmp_path / f"{name}.cfg").write_text(cfg)
        return tmp_path / f"{name}.tla"
    return write
