"""Priming any expression means the expression with every variable primed, as in
TLC: operator parameters, LET definitions, instance operators, tuples, (x + y)',
Op(x)', UNCHANGED of each (issue 14: an action priming a parameter was lost).

The figures are TLC's, recorded in tests/tla/corpus/expected.json (`Priming`,
`DropParam`) and tests/tla/errors/expected.json (`PrimedUnbound`).
"""

from __future__ import annotations

import pytest

from conftest import CORPUS, ERRORS, load_expected
from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla.compiler import Compiler

EXPECTED = load_expected(CORPUS)
FIELDS = ("result", "distinct_states", "states_generated", "depth", "violated")

# One action per form of priming in Priming.tla.
PRIMING_ACTIONS = ["DropQ", "DecA", "PickB", "IncBoth", "LetStep", "LetAct", "InstStep",
                   "Swap", "Dbl", "ViaDef", "KeepApp"]


@pytest.mark.parametrize("fast", [True, False], ids=["fast-paths", "general-paths"])
@pytest.mark.parametrize("name", ["Priming", "DropParam"])
def test_primed_parameters_and_expressions_match_tlc(name: str, fast: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(Compiler, "fast_paths", fast)
    r = explore_states(load_model(str(CORPUS / f"{name}.tla")))
    got = {f: getattr(r, f) for f in FIELDS}
    assert got == {f: EXPECTED[name][f] for f in FIELDS}


@pytest.mark.parametrize("fast", [True, False], ids=["fast-paths", "general-paths"])
def test_every_priming_form_takes_a_step(fast: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each action of Priming.tla, written with one form of priming, fires somewhere."""
    monkeypatch.setattr(Compiler, "fast_paths", fast)
    model = load_model(str(CORPUS / "Priming.tla"))
    seen, todo, fired = set(), list(model.initial_states()), set()
    while todo:
        st = todo.pop()
        if st in seen:
            continue
        seen.add(st)
        for tr in model.successors(st):
            fired.add(tr.action)
            todo.append(tr.state)
    assert sorted(fired) == sorted(PRIMING_ACTIONS)


def test_primed_expression_before_its_variable_is_assigned_is_an_error() -> None:
    want = load_expected(ERRORS)["PrimedUnbound"]
    r = explore_states(load_model(str(ERRORS / "PrimedUnbound.tla")))
    assert r.result == "error"
    assert (r.error.loc.line, r.error.loc.column) == (want["line"], want["column"])
    assert "a'" in r.error.message
