"""Memoised calls of constant operators (tla/op_memo.py) give exactly the results of the
plain calls: verdict, counts, depth, trace, successors, and the text and position of
evaluation errors, with `Compiler.memoise_operators` on and off."""

from __future__ import annotations

from pathlib import Path

import pytest

from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla.compiler import Compiler
from test_checker_fastpaths import _check

# Pick(v) is called with 0, 1, TRUE and FALSE: equal Python values, different TLA+
# values (a memo keyed by the values alone would answer Pick(TRUE) with 1, and the
# invariant's `=` would then report comparing an integer with a boolean).
KINDS = """---- MODULE Kinds ----
EXTENDS Naturals, FiniteSets
VARIABLE x
Pick(v) == CHOOSE y \\in {v} : TRUE
Below(n) == {k \\in 0..n : k < n}
Same(s) == {e : e \\in s}
Init == x = 0
Next == x' = IF x < 3 THEN x + 1 ELSE 0
Inv == /\\ Pick(x) + 0 = x
       /\\ Pick(x = 1) = (x = 1)
       /\\ Pick({x = 0}) = {x = 0}
       /\\ Pick(<<x = 2, x>>) = <<x = 2, x>>
       /\\ Cardinality(Below(x)) = x
       /\\ Same({x = 0, x > 5}) = {x = 0, x > 5}
====
"""

# An operator that fails for some arguments only: the failure is not remembered, and
# it is reported where and as the plain call reports it.
ERRORS = """---- MODULE Errs ----
EXTENDS Naturals
VARIABLE x
Big(v) == CHOOSE y \\in {v} : y > 5
Init == x = 7
Next == x' = IF x = 7 THEN 8 ELSE IF x = 8 THEN 7 - Big(x) + 1 ELSE x
Inv == Big(x) >= 6 \\/ x < 6
====
"""


def _write(tmp_path: Path, name: str, spec: str, inv: str = "Inv") -> Path:
    (tmp_path / f"{name}.tla").write_text(spec)
    (tmp_path / f"{name}.cfg").write_text(f"INIT Init\nNEXT Next\nINVARIANT {inv}\n")
    return tmp_path / f"{name}.tla"


@pytest.mark.parametrize("name,spec", [("Kinds", KINDS), ("Errs", ERRORS)])
def test_memoised_operator_calls_equal_plain_calls(name: str, spec: str, tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    tla = _write(tmp_path, name, spec)
    memo = _check(tla, None, True, monkeypatch, "memoise_operators")
    plain = _check(tla, None, False, monkeypatch, "memoise_operators")
    assert memo == plain


def test_booleans_and_integers_are_told_apart_by_the_memo(tmp_path: Path) -> None:
    tla = _write(tmp_path, "Kinds", KINDS)
    model = load_model(str(tla))
    r = explore_states(model)
    assert (r.result, r.distinct_states) == ("success", 4), r.error
    # the memo was used, and Pick's 12 arguments (0..3, TRUE, FALSE, {TRUE}, {FALSE} and
    # four tuples) are 12 entries: TRUE is not answered from 1's entry.  Below: 0..3;
    # Same: {TRUE, FALSE} and {FALSE}.
    assert sorted(len(t) for t in model.compiler.op_memo.tables.values()) == [2, 4, 12]


def test_an_evaluation_error_is_reported_not_remembered(tmp_path: Path) -> None:
    model = load_model(str(_write(tmp_path, "Errs", ERRORS)))
    r = explore_states(model)
    assert r.result == "error" and r.error is not None
    assert "CHOOSE" in r.error.message
    assert all(len(t) for t in model.compiler.op_memo.tables.values())


def test_each_model_has_its_own_memo(tmp_path: Path) -> None:
    """Two models with one operator of the same name, loaded in one process."""
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    ma = load_model(str(_write(a, "Kinds", KINDS)))
    mb = load_model(str(_write(b, "Kinds", KINDS.replace("{k \\in 0..n : k < n}", "{k \\in 0..n : k <= n}"))))
    s0 = ma.initial_states()[0]
    assert ma.eval_in_state("Cardinality(Below(3))", s0) == 3
    assert mb.eval_in_state("Cardinality(Below(3))", s0) == 4
    assert ma.eval_in_state("Cardinality(Below(3))", s0) == 3
    assert Compiler.memoise_operators
