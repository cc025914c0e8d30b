"""The protection models (PRO-01..05, models/Protection.tla and
models/RuntimeSupervisor.tla): every invariant has a non-vacuity witness, a mutant
declared in models/mutants/<Model>.toml and its requirement ID. (The witnesses are
reached and the mutants killed with TLC's counterexample length in
test_model_mutants.py; both models passing with TLC's counts is covered by
test_models.py through models/expected.json.)"""

from __future__ import annotations

import re
import pytest

from conftest import REPO
from safestate import mutants

MODELS = {name: REPO / "models" / f"{name}.tla" for name in ("Protection", "RuntimeSupervisor")}
INVARIANTS = {
    "Protection": ("INV_PRO_HAZARD_PROTECTS", "INV_PRO_LATCH", "INV_PRO_RESULT",
                   "INV_PRO_OVERRIDE", "INV_PRO_RESPONSE"),
    "RuntimeSupervisor": ("INV_SUP_RUN_GATES", "INV_SUP_INIT_TIMEOUT",
                          "INV_SUP_DEGRADED_RESTRICTED", "INV_SUP_DISPATCH_ORDER",
                          "INV_SUP_SHUTDOWN_SAFE"),
}


@pytest.mark.parametrize("name", sorted(MODELS))
def test_pro_every_invariant_has_a_witness_and_a_mutant(name: str) -> None:
    text = MODELS[name].read_text()
    targets = {m.invariant for m in mutants.load(REPO / "models" / "mutants" / f"{name}.toml")}
    for inv in INVARIANTS[name]:
        assert re.search(rf"^Witness_\w+ ==\s*\\\* {inv}", text, re.M), inv
        assert inv in targets, inv
        assert re.search(rf"^\\\* PRO-0\d.*\n(\\\*.*\n)*{inv} ==", text, re.M), \
            f"{inv} needs its requirement ID in the comment above it"
