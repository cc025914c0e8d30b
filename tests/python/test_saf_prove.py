"""SAF-01..04: every invariant of models/SafetyService.tla is proved by `safestate prove`
for every value of the timeout constants, and BMC finds each declared mutant with TLC's
counterexample length."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from conftest import REPO, run_safestate

MODEL = REPO / "models" / "SafetyService.tla"
MUTANTS = tomllib.loads((REPO / "models" / "mutants" / "SafetyService.toml").read_text())["mutant"]


def test_saf_invariants_proved_for_all_timeout_values() -> None:
    proc = run_safestate("prove", str(MODEL), "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in ("EstopTimeoutCycles", "ReportDataTimeoutCycles", "MessageIntervalCycles"):
        assert f"{name}: symbolic" in proc.stdout
    assert proc.stdout.count(": proved") == 6


@pytest.mark.parametrize("mutant", MUTANTS, ids=[m["name"] for m in MUTANTS])
def test_saf_mutant_found_by_bmc(mutant: dict, tmp_path: Path) -> None:
    source = (REPO / mutant["file"]).read_text()
    (tmp_path / "SafetyService.tla").write_text(source.replace(mutant["original"], mutant["replacement"]))
    (tmp_path / "SafetyService.cfg").write_text(MODEL.with_suffix(".cfg").read_text())
    proc = run_safestate("prove", str(tmp_path / "SafetyService.tla"), "--engine", "bmc",
                         "--depth", str(mutant["trace_length"]), "--invariant", mutant["target"],
                         "--cfg-constants", "--quiet")
    assert proc.returncode == 12, proc.stdout + proc.stderr
    assert f"State {mutant['trace_length']}:" in proc.stdout
    assert f"State {mutant['trace_length'] + 1}:" not in proc.stdout
