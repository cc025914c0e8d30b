"""The project's TLA+ models as tests (issue 4): every model passes `safestate check`
with exactly TLC's counts, and every mutant under models/mutants/ is caught on the
invariant it was written to break, with TLC's counterexample length (non-vacuity)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import REPO, run_safestate

MODELS = REPO / "models"
MUTANTS = MODELS / "mutants"


def _expected(folder: Path) -> dict:
    return json.loads((folder / "expected.json").read_text())


def _check_json(tla: Path, *extra: str) -> dict:
    proc = run_safestate("check", str(tla), "--json", *extra)
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)


@pytest.mark.parametrize("name", sorted(_expected(MODELS)))
def test_model_passes_every_invariant_with_tlc_counts(name: str) -> None:
    want = _expected(MODELS)[name]
    got = _check_json(MODELS / f"{name}.tla", "--workers", "2")
    assert got["result"] == "success", got.get("violated") or got.get("error")
    assert (got["distinct_states"], got["states_generated"], got["depth"]) == (
        want["distinct_states"], want["states_generated"], want["depth"])


@pytest.mark.parametrize("name", sorted(_expected(MUTANTS)))
def test_mutant_is_caught_on_its_target_invariant(name: str) -> None:
    want = _expected(MUTANTS)[name]
    got = _check_json(MUTANTS / f"{name}.tla")
    assert got["result"] == "safety failure"
    assert got["violated"] == want["violated"]
    assert len(got["trace"]["states"]) == want["trace_length"]
    assert got["distinct_states"] == want["distinct_states_at_violation"]
