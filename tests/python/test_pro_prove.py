"""PRO-01..05: every invariant of models/Protection.tla and models/RuntimeSupervisor.tla
is proved by `safestate prove` for every value of the thresholds, the response budget and
the init timeout. (BMC finds each declared mutant with TLC's counterexample length in
test_prove_mutants.py.)"""

from __future__ import annotations


import pytest

from conftest import REPO, run_safestate

SYMBOLIC = {
    "Protection": ("TempLimit", "VoltMin", "VoltMax", "ResponseBudgetTicks"),
    "RuntimeSupervisor": ("InitTimeoutTicks",),
}


@pytest.mark.parametrize("name", sorted(SYMBOLIC))
def test_pro_invariants_proved_for_all_constant_values(name: str) -> None:
    proc = run_safestate("prove", str(REPO / "models" / f"{name}.tla"), "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for constant in SYMBOLIC[name]:
        assert f"{constant}: symbolic" in proc.stdout
    # every invariant of the CI cfg (TypeOK included) is proved
    cfg = (REPO / "models" / f"{name}.cfg").read_text()
    listed = cfg.split("INVARIANTS", 1)[1].split()
    assert proc.stdout.count(": proved") == len(listed), proc.stdout
