"""The project's TLA+ models as tests (issues 4, 9, 17): every model passes `safestate check`
with exactly TLC's counts; every flagship property has a witness and a killing mutant, and
the mutants cover every RSM requirement. (The witnesses are reached and the mutants killed
in test_model_mutants.py, for every registered system.)"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import REPO, run_safestate
from safestate import mutants
from safestate.checker.cfg import parse_config

MODELS = REPO / "models"
# The SafetyService mutants have their own tests (test_saf_model.py).
FLAGSHIP = "SystemStateManager"
MUTANTS = mutants.load(MODELS / "mutants" / f"{FLAGSHIP}.toml")


def _expected(folder: Path) -> dict:
    return json.loads((folder / "expected.json").read_text())


def _check_json(tla: Path, *extra: str) -> dict:
    proc = run_safestate("check", str(tla), "--json", *extra)
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)


# Every model and cfg of models/expected.json is checked by both engines, except where
# the Python engine's run costs more than the suite can pay: the flagship's CI cfg (71
# CPU s) is checked by the Python engine in its reduced cfg (every construct of the
# model, 11 s) and in full by the main job (scripts/main.sh, the evidence step's
# `safestate check`); SafetyServicePeers (29 s) shares its module with SafetyService.
# The native engine is itself compared with the Python engine on every spec it accepts
# (test_checker_native_engine.py).
PYTHON_ENGINE_TOO_DEAR = {"SystemStateManager", "SafetyServicePeers"}


def _cases() -> list[tuple[str, str]]:
    names = sorted(_expected(MODELS))
    return [(n, "native") for n in names] + [(n, "python") for n in names if n not in PYTHON_ENGINE_TOO_DEAR]


@pytest.mark.parametrize(("name", "engine"), _cases())
def test_model_passes_every_invariant_with_tlc_counts(name: str, engine: str) -> None:
    want = _expected(MODELS)[name]
    model = want.get("model", name)  # an entry for a second cfg names its model
    # `--engine native` refuses a model outside its subset instead of falling back: a
    # model that stops being accepted fails here rather than silently using Python.
    # The Python engine's flagship run uses 2 workers: its sharded search on a real model.
    extra = ["--workers", "2"] if (engine, model) == ("python", FLAGSHIP) else []
    got = _check_json(MODELS / f"{model}.tla", "--config", str(MODELS / f"{name}.cfg"), "--engine", engine, *extra)
    assert got["result"] == "success", got.get("violated") or got.get("error")
    assert (got["distinct_states"], got["states_generated"], got["depth"]) == (
        want["distinct_states"], want["states_generated"], want["depth"])


def _flagship_properties() -> list[str]:
    cfg = parse_config(str(MODELS / f"{FLAGSHIP}.cfg"))
    return [e.name for e in cfg.invariants if e.name != "TypeOK"]


def test_every_property_has_a_witness() -> None:
    """Each is checked reachable by test_model_mutants.py."""
    witnesses = set(mutants.witnesses(MODELS / f"{FLAGSHIP}.tla"))
    assert {f"Witness_{p}" for p in _flagship_properties()} <= witnesses


def test_every_property_has_a_killing_mutant() -> None:
    killed = {m.invariant for m in MUTANTS if m.expect == "violated"}
    assert set(_flagship_properties()) <= killed, set(_flagship_properties()) - killed


def test_mutants_cover_every_checkable_rsm_requirement() -> None:
    covered = {m.requirement for m in MUTANTS if m.expect == "violated"}
    want = {f"RSM-{n:02d}" for n in range(1, 18)}
    assert want <= covered, want - covered
