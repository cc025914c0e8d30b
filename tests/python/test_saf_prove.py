"""SAF-01..04 and the message-level properties of issue 30 (UCA-1..6): every invariant
of models/SafetyService.cfg is proved by `safestate prove` for every value of the
timeout constants. (BMC finds each declared mutant with TLC's counterexample length in
test_prove_mutants.py.)"""

from __future__ import annotations

import re

from conftest import REPO, run_safestate

MODEL = REPO / "models" / "SafetyService.tla"
CFG_INVARIANTS = re.search(r"^INVARIANTS\n((?:[ \t]+\w+\n?)+)", (REPO / "models" / "SafetyService.cfg").read_text(),
                           re.M).group(1).split()  # type: ignore[union-attr]


def test_saf_invariants_proved_for_all_timeout_values() -> None:
    proc = run_safestate("prove", str(MODEL), "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in ("EstopTimeoutCycles", "ReportDataTimeoutCycles", "MessageIntervalCycles"):
        assert f"{name}: symbolic" in proc.stdout
    assert "INV_SAF_ATTACKER_NO_EFFECT" in CFG_INVARIANTS and "INV_SAF_ASKS_AGAIN" in CFG_INVARIANTS
    for inv in CFG_INVARIANTS:
        assert re.search(rf"^{inv}: proved", proc.stdout, re.M), inv
