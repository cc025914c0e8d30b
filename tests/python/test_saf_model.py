"""The Safety service model (SAF-01..04, models/SafetyService.tla): every invariant's
situation is reachable (non-vacuity witnesses), also the protocol's situations with the
explicit peers (models/SafetyServicePeers.tla), and every mutant declared in
models/mutants/SafetyService.toml is caught on its target invariant with TLC's
counterexample length. (Both models passing with TLC's counts is covered by
test_models.py through models/expected.json.)"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from conftest import REPO
from declared_mutants import check_variant, mutants_of, mutated_source, witnesses_of

MODEL = REPO / "models" / "SafetyService.tla"
PEERS = REPO / "models" / "SafetyServicePeers.tla"
MUTANTS = mutants_of("SafetyService")
WITNESSES = witnesses_of(MODEL)
PEER_WITNESSES = witnesses_of(PEERS)


def _check(folder: Path, tla_text: str, invariant: str, model: Path = MODEL) -> dict:
    """Checks `model` (with SafetyService.tla replaced by `tla_text`) in `folder`."""
    return check_variant(folder, model, invariant, {MODEL.name: tla_text})


def test_every_invariant_has_witnesses() -> None:
    assert len(WITNESSES) >= 5
    for inv in ("INV_SAF_EMERGENCY", "INV_SAF_RELEASE_ONLY_OPERATIONAL",
                "INV_SAF_NO_OPERATIONAL_IN_DANGER", "INV_SAF_FAULT_ABSORBING",
                "INV_SAF_SET_STATE_WITH_CONTROL"):
        assert re.search(rf"^Witness_\w+ ==\s*\\\* {inv}", MODEL.read_text(), re.M), inv


@pytest.mark.parametrize("witness", WITNESSES)
def test_saf_witness_situation_is_reachable(witness: str, tmp_path: Path) -> None:
    got = _check(tmp_path, MODEL.read_text(), witness)
    assert got["result"] == "safety failure" and got["violated"] == witness


@pytest.mark.parametrize("witness", PEER_WITNESSES)
def test_saf_protocol_situation_with_explicit_peers_is_reachable(witness: str, tmp_path: Path) -> None:
    got = _check(tmp_path, MODEL.read_text(), witness, PEERS)
    assert got["result"] == "safety failure" and got["violated"] == witness


@pytest.mark.parametrize("mutant", MUTANTS, ids=[m["name"] for m in MUTANTS])
def test_saf_mutant_is_caught_on_its_target_invariant(mutant: dict, tmp_path: Path) -> None:
    got = _check(tmp_path, mutated_source(mutant), mutant["target"])
    assert got["result"] == "safety failure"
    assert got["violated"] == mutant["target"]
    assert len(got["trace"]["states"]) == mutant["trace_length"]
