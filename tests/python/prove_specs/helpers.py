"""Shared helpers of the tests/python/test_prove_* tests: run `safestate prove` in-process."""

from __future__ import annotations

import json
import os
from typing import Any

import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
if os.path.join(ROOT, "python") not in sys.path:  # run from a checkout without installing
    sys.path.insert(0, os.path.join(ROOT, "python"))
SPECS = os.path.join(ROOT, "tests", "python", "prove_specs")
MODELS = os.path.join(ROOT, "models")


def spec(name: str) -> str:
    return os.path.join(SPECS, name)


def prove(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, dict[str, Any] | None, str]:
    """Runs the prove CLI; returns (exit code, parsed JSON or None, stderr)."""
    from safestate.prove.cli import main
    code = main(list(argv) + ["--json", "--quiet"])
    out, err = capsys.readouterr()
    return code, (json.loads(out) if out.strip() else None), err


def by_invariant(report: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {r["invariant"]: r for r in report["results"]}
