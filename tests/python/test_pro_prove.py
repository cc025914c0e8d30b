"""PRO-01..05: every invariant of models/Protection.tla and models/RuntimeSupervisor.tla
is proved by `safestate prove` for every value of the thresholds, the response budget and
the init timeout, and BMC finds each declared mutant with TLC's counterexample length."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import REPO, run_safestate
from declared_mutants import mutants_of, mutated_source

SYMBOLIC = {
    "Protection": ("TempLimit", "VoltMin", "VoltMax", "ResponseBudgetTicks"),
    "RuntimeSupervisor": ("InitTimeoutTicks",),
}
MUTANTS = [(name, m) for name in SYMBOLIC for m in mutants_of(name)]


@pytest.mark.parametrize("name", sorted(SYMBOLIC))
def test_pro_invariants_proved_for_all_constant_values(name: str) -> None:
    proc = run_safestate("prove", str(REPO / "models" / f"{name}.tla"), "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for constant in SYMBOLIC[name]:
        assert f"{constant}: symbolic" in proc.stdout
    assert proc.stdout.count(": proved") == 6


@pytest.mark.parametrize("name,mutant", MUTANTS, ids=[m["name"] for _, m in MUTANTS])
def test_pro_mutant_found_by_bmc(name: str, mutant: dict, tmp_path: Path) -> None:
    model = REPO / "models" / f"{name}.tla"
    (tmp_path / model.name).write_text(mutated_source(mutant))
    (tmp_path / model.with_suffix(".cfg").name).write_text(model.with_suffix(".cfg").read_text())
    proc = run_safestate("prove", str(tmp_path / model.name), "--engine", "bmc",
                         "--depth", str(mutant["trace_length"]), "--invariant", mutant["target"],
                         "--cfg-constants", "--quiet")
    assert proc.returncode == 12, proc.stdout + proc.stderr
    assert f"State {mutant['trace_length']}:" in proc.stdout
    assert f"State {mutant['trace_length'] + 1}:" not in proc.stdout
