"""The protection models (PRO-01..05, models/Protection.tla and
models/RuntimeSupervisor.tla): every invariant's situation is reachable (non-vacuity
witnesses), and every mutant declared in models/mutants/<Model>.toml is caught on its
target invariant with TLC's counterexample length. (Both models passing with TLC's
counts is covered by test_models.py through models/expected.json.)"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from conftest import REPO
from declared_mutants import check_variant, mutants_of, mutated_source, witnesses_of

MODELS = {name: REPO / "models" / f"{name}.tla" for name in ("Protection", "RuntimeSupervisor")}
INVARIANTS = {
    "Protection": ("INV_PRO_HAZARD_PROTECTS", "INV_PRO_LATCH", "INV_PRO_RESULT",
                   "INV_PRO_OVERRIDE", "INV_PRO_RESPONSE"),
    "RuntimeSupervisor": ("INV_SUP_RUN_GATES", "INV_SUP_INIT_TIMEOUT",
                          "INV_SUP_DEGRADED_RESTRICTED", "INV_SUP_DISPATCH_ORDER",
                          "INV_SUP_SHUTDOWN_SAFE"),
}
WITNESSES = [(name, w) for name, path in MODELS.items() for w in witnesses_of(path)]
MUTANTS = [(name, m) for name in MODELS for m in mutants_of(name)]


@pytest.mark.parametrize("name", sorted(MODELS))
def test_pro_every_invariant_has_a_witness_and_a_mutant(name: str) -> None:
    text = MODELS[name].read_text()
    targets = {m["target"] for m in mutants_of(name)}
    for inv in INVARIANTS[name]:
        assert re.search(rf"^Witness_\w+ ==\s*\\\* {inv}", text, re.M), inv
        assert inv in targets, inv
        assert re.search(rf"^\\\* PRO-0\d.*\n(\\\*.*\n)*{inv} ==", text, re.M), \
            f"{inv} needs its requirement ID in the comment above it"


@pytest.mark.parametrize("name,witness", WITNESSES, ids=[f"{n}-{w}" for n, w in WITNESSES])
def test_pro_witness_situation_is_reachable(name: str, witness: str, tmp_path: Path) -> None:
    got = check_variant(tmp_path, MODELS[name], witness)
    assert got["result"] == "safety failure" and got["violated"] == witness


@pytest.mark.parametrize("name,mutant", MUTANTS, ids=[m["name"] for _, m in MUTANTS])
def test_pro_mutant_is_caught_on_its_target_invariant(name: str, mutant: dict,
                                                      tmp_path: Path) -> None:
    got = check_variant(tmp_path, MODELS[name], mutant["target"],
                        {MODELS[name].name: mutated_source(mutant)})
    assert got["result"] == "safety failure"
    assert got["violated"] == mutant["target"]
    assert len(got["trace"]["states"]) == mutant["trace_length"]
