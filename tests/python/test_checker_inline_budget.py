"""The Python engine's inlining of small operators has a budget (tla/inline.py
MAX_INLINED_NODES): operators that call each other twice at every level would otherwise
be copied 2^depth times into their caller, and the model's load time goes to compiling
the copies (the press's state-chain operators did: 21 s of a 24 s load).  Past the
budget a call stays a call: the same states, only compiled once."""

from __future__ import annotations

from pathlib import Path

import pytest

from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla import inline
from safestate.tla.compiler import Compiler

LEVELS = 12


def _nested_spec(folder: Path) -> Path:
    """Op0(v) calls Op1 twice, Op1 calls Op2 twice, ... : 2^LEVELS inlined copies of the last."""
    ops = [f"Op{LEVELS}(v) == (v * 3 + 1) % 7"]  # defined before use, the deepest first
    ops += [f"Op{i}(v) == IF v > {i} THEN Op{i + 1}(v - 1) ELSE Op{i + 1}(v + 1)" for i in reversed(range(LEVELS))]
    body = "\n".join(ops) + "\nInit == x = 0\nNext == x' = Op0(x + 1) /\\ x < 6\n"
    (folder / "Nested.tla").write_text(f"---- MODULE Nested ----\nEXTENDS Naturals\nVARIABLES x\n{body}====\n")
    (folder / "Nested.cfg").write_text("INIT Init\nNEXT Next\n")
    return folder / "Nested.tla"


def _states(tla: Path) -> tuple[int, int, list]:
    model = load_model(str(tla))
    r = explore_states(model)
    return model.compiler._inlined_nodes, r.distinct_states, sorted(model.initial_states())


def test_inlining_stops_at_its_budget_and_the_states_stay_the_same(tmp_path: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    tla = _nested_spec(tmp_path)
    unbounded_budget = 10 ** 9
    monkeypatch.setattr(inline, "MAX_INLINED_NODES", unbounded_budget)
    inlined_all, distinct_all, init_all = _states(tla)
    monkeypatch.setattr(inline, "MAX_INLINED_NODES", 2_000)
    inlined, distinct, init = _states(tla)
    assert inlined_all > 2_000 >= inlined, "nested calls are inlined up to the budget and no further"
    assert (distinct, init) == (distinct_all, init_all)
    monkeypatch.setattr(Compiler, "fast_paths", False)  # no inlining at all: the reference
    assert _states(tla)[1:] == (distinct_all, init_all)
