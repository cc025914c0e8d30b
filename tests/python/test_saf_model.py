"""The Safety service model (SAF-01..04, models/SafetyService.tla): every invariant's
situation is reachable (non-vacuity witnesses), also the protocol's situations with the
explicit peers (models/SafetyServicePeers.tla), and every mutant declared in
models/mutants/SafetyService.toml is caught on its target invariant with TLC's
counterexample length. (Both models passing with TLC's counts is covered by
test_models.py through models/expected.json.)"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import pytest

from conftest import REPO, run_safestate

MODEL = REPO / "models" / "SafetyService.tla"
PEERS = REPO / "models" / "SafetyServicePeers.tla"
MUTANTS = tomllib.loads((REPO / "models" / "mutants" / "SafetyService.toml").read_text())["mutant"]
WITNESSES = sorted(set(re.findall(r"^(Witness_\w+) ==", MODEL.read_text(), re.M)))
PEER_WITNESSES = sorted(set(re.findall(r"^(Witness_\w+) ==", PEERS.read_text(), re.M)))


def _cfg_with_only(model: Path, invariant: str) -> str:
    """The model's .cfg (constants, INIT, NEXT, VIEW) with one invariant listed."""
    head = model.with_suffix(".cfg").read_text().split("INVARIANTS")[0]
    return f"{head}INVARIANTS\n    {invariant}\n"


def _check(folder: Path, tla_text: str, invariant: str, model: Path = MODEL) -> dict:
    """Checks `model` (with SafetyService.tla replaced by `tla_text`) in `folder`."""
    (folder / "SafetyService.tla").write_text(tla_text)
    if model != MODEL:
        (folder / model.name).write_text(model.read_text())
    (folder / model.with_suffix(".cfg").name).write_text(_cfg_with_only(model, invariant))
    proc = run_safestate("check", str(folder / model.name), "--json")
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)


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
    source = (REPO / mutant["file"]).read_text()
    assert source.count(mutant["original"]) == 1, "the original text must occur exactly once"
    got = _check(tmp_path, source.replace(mutant["original"], mutant["replacement"]),
                 mutant["target"])
    assert got["result"] == "safety failure"
    assert got["violated"] == mutant["target"]
    assert len(got["trace"]["states"]) == mutant["trace_length"]
