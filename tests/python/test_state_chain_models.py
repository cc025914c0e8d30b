"""SCH-01..05 models (docs/design/state-chain.md, hydraulic-press.md) as tests: the flat
press violates INV-PRESS with the accident trace (and the committed ITF is that trace);
every StateChainDoc mutant is caught by `safestate check` with TLC's figures (the press's
mutants belong to registered systems and run in test_model_mutants.py, with the same
assertions); the StateChain witnesses are reached. The full chain models take minutes, so their runs (1,667 and 1,929
distinct states, TLC-equal) are recorded in models/README.md, not repeated here."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import REPO, run_safestate
from safestate import mutants

MODELS = REPO / "models"
# StateChainDoc is the one chain model that is not a registered system (systems/*): the
# HydraulicPress and HydraulicPressFlat mutants are checked by test_model_mutants.py.
MUTANTS = mutants.load(MODELS / "mutants" / "StateChainDoc.toml")
WITNESSES = ["Witness_DeepActive", "Witness_ParallelExited", "Witness_NestedEntry",
             "Witness_CrossRejected", "Witness_SelfTransition", "Witness_RunNested"]


def _check_json(tla: Path, *extra: str) -> dict:
    proc = run_safestate("check", str(tla), "--json", *extra)
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)


def _events(trace: dict) -> list[str]:
    return [s["event"] for s in trace["states"]][1:]


def test_SCH05_flat_press_violates_INV_PRESS_with_the_accident() -> None:
    got = _check_json(MODELS / "HydraulicPressFlat.tla")
    assert got["result"] == "safety failure" and got["violated"] == "INV_PRESS"
    assert _events(got["trace"]) == ["motor_on", "start", "motor_off", "motor_on"]
    last = got["trace"]["states"][-1]
    assert set(last["outputs"]["#set"]) == {"motor", "feed_valve"}
    assert (got["distinct_states"], got["states_generated"], got["depth"]) == (72, 422, 5)  # TLC's


def test_SCH05_committed_accident_itf_is_the_checkers_counterexample() -> None:
    got = _check_json(MODELS / "HydraulicPressFlat.tla")
    committed = json.loads((MODELS / "traces" / "HydraulicPressFlat_INV_PRESS.itf.json").read_text())
    assert committed["states"] == got["trace"]["states"]


@pytest.mark.parametrize("mutant", MUTANTS, ids=[m.id for m in MUTANTS])
def test_chain_mutant_is_caught_with_tlc_figures(mutant: mutants.Mutant, tmp_path: Path) -> None:
    got = _check_json(mutants.materialise(mutant, MODELS, tmp_path))
    assert got["result"] == "safety failure", got.get("error")
    assert got["violated"] == mutant.invariant
    assert len(got["trace"]["states"]) == mutant.trace_length
    assert got["distinct_states"] == mutant.distinct_states


@pytest.mark.parametrize("witness", WITNESSES)
def test_state_chain_witness_is_reached(witness: str, tmp_path: Path) -> None:
    for f in MODELS.glob("*.tla"):
        (tmp_path / f.name).write_text(f.read_text())
    cfg = (MODELS / "StateChainDoc.cfg").read_text().split("INVARIANTS")[0]
    (tmp_path / "StateChainDoc.cfg").write_text(cfg + f"INVARIANT {witness}\n")
    got = _check_json(tmp_path / "StateChainDoc.tla")
    assert got["result"] == "safety failure" and got["violated"] == witness
