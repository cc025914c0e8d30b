"""Agreement with the explicit checker: on the checked .cfg (every constant at its .cfg
value), BMC finds each mutant of every registered system (systems/<Name>/system.toml
names its mutant file; generated as patches into a temporary folder) violating its invariant, with a counterexample exactly as long as
TLC's (BMC deepens one step at a time, so its counterexample is a shortest one).
Mutants with counterexamples longer than MAX_BMC_LENGTH states are left to the explicit
checker (tests/python/test_model_mutants.py), to keep the suite's time bounded."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from prove_specs.helpers import MODELS, by_invariant, prove  # noqa: I001 (puts python/ on sys.path)
from safestate import mutants
from safestate.systems import registry

MAX_BMC_LENGTH = 6
# Left to the explicit checker as well:
# - HydraulicPress: its translation needs its proof plan's typed call log and takes
#   minutes (docs/prove.md); without the plan it is refused ("DOMAIN of a value").
BMC_LEFT_OUT_SYSTEMS = {"HydraulicPress"}
# A set-valued variable is represented only inside its TypeOK domain (one Boolean per
# element), so a step assigning an element outside it cannot be represented: both
# engines report it through the 'type' obligation of the assignment, as a TypeOK
# violation whose trace ends in the state before that step (one state shorter than
# TLC's, whose last state is outside the representation). Likewise a record variable:
# SafetyService's shadow service copies the unbounded estop_age of its mutant.
TYPE_STEP = "FLAT_TypeOK_output_stage_energises_none"
TYPE_STEPS = {TYPE_STEP, "SAF_TypeOK_estop_age_unbounded"}
ENTRIES = [m for s in registry.load_all(Path(MODELS).parent / "systems") for m in mutants.of_system(s)
           if m.expect == "violated" and m.trace_length and m.trace_length <= MAX_BMC_LENGTH
           and s.name not in BMC_LEFT_OUT_SYSTEMS]


def _materialise(m: mutants.Mutant, tmp_path: Path) -> tuple[str, str]:
    tla = mutants.materialise(m, Path(MODELS), tmp_path)
    return str(tla), os.path.splitext(str(tla))[0] + ".cfg"


@pytest.mark.parametrize("entry", [pytest.param(m, id=m.id) for m in ENTRIES])
def test_bmc_agrees_with_tlc(entry: mutants.Mutant, tmp_path: Path, capsys) -> None:
    tla, cfg = _materialise(entry, tmp_path)
    n = int(entry.trace_length or 0)
    code, rep, err = prove(capsys, tla, "--config", cfg, "--proofs", "/dev/null",
                           "--cfg-constants", "--engine", "bmc", "--depth", str(n - 1),
                           "--invariant", entry.invariant)
    assert rep is not None, err
    r = by_invariant(rep)[entry.invariant]
    assert r["status"] == "violated", f"{entry.id}: BMC found no violation of {entry.invariant} in {n} states"
    assert len(r["trace"]["states"]) == (n - 1 if entry.name in TYPE_STEPS else n)
    assert code == 12


def test_kinduction_never_proves_a_mutant(tmp_path: Path, capsys) -> None:
    """Soundness check: k-induction's base case reaches the violation instead of a proof."""
    entry = min((e for e in ENTRIES if e.model == "SystemStateManager"), key=lambda e: int(e.trace_length or 0))
    tla, cfg = _materialise(entry, tmp_path)
    n = int(entry.trace_length or 0)
    code, rep, err = prove(capsys, tla, "--config", cfg, "--proofs", "/dev/null",
                           "--cfg-constants", "--engine", "kind", "--depth", str(n), "--invariant", entry.invariant)
    assert rep is not None, err
    r = by_invariant(rep)[entry.invariant]
    assert r["status"] == "violated" and len(r["trace"]["states"]) == n and code == 12



def test_kinduction_reports_a_step_out_of_typeok(tmp_path: Path, capsys) -> None:
    """A step that leaves TypeOK's domain (the flat press drives the placeholder output
    "none") must not vanish from the translation and leave TypeOK 'proved': its type
    obligation fails on the initial state, and TypeOK is reported violated (exit 12)."""
    entry = next(e for e in ENTRIES if e.name == TYPE_STEP)
    tla, cfg = _materialise(entry, tmp_path)
    code, rep, err = prove(capsys, tla, "--config", cfg, "--proofs", "/dev/null", "--cfg-constants",
                           "--invariant", "TypeOK")
    assert rep is not None, err
    r = by_invariant(rep)["TypeOK"]
    assert r["status"] == "violated" and code == 12
    assert "the value given to outputs is in its TypeOK domain" in r["undefined"]
    assert len(r["trace"]["states"]) == int(entry.trace_length or 0) - 1  # the state after it is not shown
