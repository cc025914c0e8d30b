"""Joint k-induction (`safestate prove`): invariants with the same k and strengthening are
proved by one induction of their conjunction, each still reported by name; when the
conjunction is not proved (a mutant), every invariant is proved on its own, so the
violated one is named with its own counterexample."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from prove_specs.helpers import MODELS, ROOT, by_invariant, prove  # noqa: I001 (puts python/ on sys.path)
from safestate import mutants

PLAN = os.path.join(ROOT, "proofs", "PLCopenAxis.toml")
MUTANTS = [m for m in mutants.load(Path(MODELS) / "mutants" / "PLCopenAxis.toml") if m.expect == "violated"]


def test_invariants_of_one_group_are_proved_by_one_induction_and_each_reported(capsys) -> None:
    code, rep, err = prove(capsys, os.path.join(MODELS, "PLCopenAxis.tla"), "--proofs", PLAN)
    assert rep is not None, err
    res = by_invariant(rep)
    assert len(res) > 1 and code == 0
    for name, r in res.items():
        assert r["status"] == "proved", name
        assert "one induction with the" in r["note"], name


@pytest.mark.parametrize("entry", MUTANTS, ids=[m.id for m in MUTANTS])
def test_a_violated_invariant_is_reported_by_name_when_the_joint_proof_fails(entry: mutants.Mutant, tmp_path: Path,
                                                                             capsys) -> None:
    tla = mutants.materialise(entry, Path(MODELS), tmp_path)
    code, rep, err = prove(capsys, str(tla), "--proofs", PLAN, "--cfg-constants")
    assert rep is not None, err
    res = by_invariant(rep)
    target = res[entry.invariant]
    assert target["status"] == "violated", f"{entry.id}: {target}"
    assert target["trace"] is not None and len(target["trace"]["states"]) == entry.trace_length
    assert not any("one induction with the" in r["note"] for r in res.values())
    assert code == 12
