"""The Safety service model (SAF-01..04, models/SafetyService.tla): every invariant has a
non-vacuity witness, and the protocol's situations with the explicit peers
(models/SafetyServicePeers.tla) are reachable. (The witnesses of SafetyService.tla are
reached and its mutants killed in test_model_mutants.py; both models passing with TLC's
counts is covered by test_models.py through models/expected.json.)"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from conftest import REPO, run_safestate
from safestate import mutants

MODEL = REPO / "models" / "SafetyService.tla"
PEERS = REPO / "models" / "SafetyServicePeers.tla"
PEER_WITNESSES = mutants.witnesses(PEERS)


def test_every_invariant_has_witnesses() -> None:
    assert len(mutants.witnesses(MODEL)) >= 5
    for inv in ("INV_SAF_EMERGENCY", "INV_SAF_RELEASE_ONLY_OPERATIONAL",
                "INV_SAF_NO_OPERATIONAL_IN_DANGER", "INV_SAF_FAULT_ABSORBING",
                "INV_SAF_SET_STATE_WITH_CONTROL"):
        assert re.search(rf"^Witness_\w+ ==\s*\\\* {inv}", MODEL.read_text(), re.M), inv


@pytest.mark.parametrize("witness", PEER_WITNESSES)
def test_saf_protocol_situation_with_explicit_peers_is_reachable(witness: str, tmp_path: Path) -> None:
    proc = run_safestate("check", str(mutants.variant(PEERS, witness, tmp_path)), "--json")
    got = json.loads(proc.stdout)
    assert got["result"] == "safety failure" and got["violated"] == witness
