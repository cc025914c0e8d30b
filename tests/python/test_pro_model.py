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
                          "INV_SUP_SHUTDOWN_SAFE", "INV_SUP_PROTECTION_RUNS", "INV_SUP_FAIL_SAFE",
                          "INV_SUP_SHUTDOWN_ON_REQUEST", "INV_SUP_RUN_WHEN_READY",
                          "INV_SUP_SHUTDOWN_PROGRESS", "INV_SUP_SAFE_FROM_STEP1"),
}
DESIGN = REPO / "docs" / "design" / "protection.md"


@pytest.mark.parametrize("name", sorted(MODELS))
def test_pro_every_invariant_has_a_witness_and_a_mutant(name: str) -> None:
    text = MODELS[name].read_text()
    targets = {m.invariant for m in mutants.load(REPO / "models" / "mutants" / f"{name}.toml")}
    for inv in INVARIANTS[name]:
        assert re.search(rf"^Witness_\w+ ==\s*\\\* {inv}", text, re.M), inv
        assert inv in targets, inv
        assert re.search(rf"^\\\* PRO-0\d.*\n(\\\*.*\n)*{inv} ==", text, re.M), \
            f"{inv} needs its requirement ID in the comment above it"


def _uca_rows() -> list[list[str]]:
    """The rows of the design page's hazard table (section 12): UCA, ..., invariant, mutants."""
    text = DESIGN.read_text()
    section = text[text.index("## 12. Hazards"):text.index("## 13.")]
    return [[c.strip() for c in line.strip("|").split("|")]
            for line in section.splitlines() if line.startswith("| UCA-")]


def test_issue31_every_hazard_names_a_checked_invariant_and_a_declared_mutant() -> None:
    """Issue 31 items 4 and 5: each unsafe control action of the design page is stated by
    an invariant of the model's CI cfg, and each mutant it names (the unsafe behaviour)
    is declared against that invariant, so `safestate check` alone kills it
    (test_model_mutants.py runs them)."""
    rows = _uca_rows()
    assert {r[0] for r in rows} >= {f"UCA-P{i}" for i in range(1, 8)} | {f"UCA-S{i}" for i in range(1, 11)}
    declared = {name: {m.name: m.invariant for m in mutants.load(REPO / "models" / "mutants" / f"{name}.toml")}
                for name in MODELS}
    for row in rows:
        model = "Protection" if row[0].startswith("UCA-P") else "RuntimeSupervisor"
        inv = row[-2].strip("`")
        cfg = (REPO / "models" / f"{model}.cfg").read_text()
        assert re.search(rf"^\s+{inv}$", cfg, re.M), f"{row[0]}: {inv} not checked by {model}.cfg"
        for suffix in re.findall(r"`(?:SUP_)?…_(\w+)`", row[-1]):
            hits = [mid for mid in declared[model] if mid.endswith("_" + suffix)]
            assert hits, f"{row[0]}: no mutant ending in {suffix}"
            assert all(declared[model][h] == inv for h in hits), f"{row[0]}: {hits} not aimed at {inv}"


def test_issue31_item4_degraded_shutdown_and_init_timer_mutants_are_declared() -> None:
    """Issue 31 item 4: nothing dispatched in Degraded, monitoring/control stopped before
    safety at shutdown, the init timer frozen, and the dispatcher gate are mutants of the
    supervisor model aimed at the invariants that state them."""
    declared = {m.name: m.invariant for m in mutants.load(REPO / "models" / "mutants" / "RuntimeSupervisor.toml")}
    assert declared["SUP_INV_SUP_PROTECTION_RUNS_nothing_dispatched_in_degraded"] == "INV_SUP_PROTECTION_RUNS"
    assert declared["SUP_INV_SUP_SHUTDOWN_SAFE_monitoring_control_stopped_before_safety"] == "INV_SUP_SHUTDOWN_SAFE"
    assert declared["SUP_INV_SUP_INIT_TIMEOUT_init_timer_frozen"] == "INV_SUP_INIT_TIMEOUT"
    assert declared["SUP_INV_SUP_DEGRADED_RESTRICTED_dispatch_without_dispatcher"] == "INV_SUP_DEGRADED_RESTRICTED"
