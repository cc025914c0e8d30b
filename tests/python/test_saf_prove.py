"""SAF-01..04: every invariant of models/SafetyService.tla is proved by `safestate prove`
for every value of the timeout constants. (BMC finds each declared mutant with TLC's
counterexample length in test_prove_mutants.py.)"""

from __future__ import annotations


from conftest import REPO, run_safestate

MODEL = REPO / "models" / "SafetyService.tla"


def test_saf_invariants_proved_for_all_timeout_values() -> None:
    proc = run_safestate("prove", str(MODEL), "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in ("EstopTimeoutCycles", "ReportDataTimeoutCycles", "MessageIntervalCycles"):
        assert f"{name}: symbolic" in proc.stdout
    assert proc.stdout.count(": proved") == 6
