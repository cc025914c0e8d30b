"""Memoised constant folding (tla/fold_memo.py, issue 9): a constant expression expanded
at many sites is compiled and folded once, and never hands one site another site's value.

Each model is loaded with the fast paths on (memo) and off (no folding at all) and the
observable results are compared: initial states, successors, and the text and position
of load and evaluation errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla.compiler import Compiler
from safestate.tla.errors import TlaError

CFG = "INIT Init\nNEXT Next\n"


def _write(folder: Path, name: str, body: str, variables: str = "x, y, z") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{name}.tla").write_text(f"---- MODULE {name} ----\nEXTENDS Naturals\nVARIABLES {variables}\n"
                                        f"{body}\n====\n")
    (folder / f"{name}.cfg").write_text(CFG)
    return folder / f"{name}.tla"


def _observe(tla: Path, fast: bool, monkeypatch: pytest.MonkeyPatch) -> tuple:
    """Initial states and their successors, or the load / evaluation error."""
    monkeypatch.setattr(Compiler, "fast_paths", fast)
    try:
        model = load_model(str(tla))
        r = explore_states(model)
    except TlaError as e:
        return ("load error", e.kind, e.message, str(e.loc))
    if r.error is not None:
        return ("error", r.error.kind, r.error.message, str(r.error.loc))
    init = model.initial_states()
    return (init, [[t.state for t in model.successors(s)] for s in init])


def _memo_hits(tla: Path) -> int:
    return load_model(str(tla)).compiler.fold_memo.hits


def test_each_binding_of_a_definition_gets_its_own_value(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """One definition expanded in Init under different arguments (literals, LET names bound
    to different values, nested operators passing their parameter on) and reused under the
    same ones: every site gets the value of its own binding."""
    tla = _write(tmp_path, "Bindings", """
Pair(a) == {a, a + 1}
Twice(b) == Pair(b) \\cup Pair(b + 10)
Init == /\\ x = Pair(1) \\cup Pair(1)
        /\\ y = LET k == 2 IN Twice(k)
        /\\ z = LET k == 3 IN Twice(k)
Next == UNCHANGED <<x, y, z>>""")
    fast = _observe(tla, True, monkeypatch)
    assert fast == _observe(tla, False, monkeypatch)
    assert fast[0] == [(frozenset({1, 2}), frozenset({2, 3, 12, 13}), frozenset({3, 4, 13, 14}))]
    monkeypatch.setattr(Compiler, "fast_paths", True)
    assert _memo_hits(tla) > 0  # Pair(1)'s body is folded once for both of its sites


def test_two_versions_of_a_model_in_one_process_keep_their_own_values(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Two mutants of one model (same file names, one definition differs) loaded one after
    the other in the same process: the second is not served the first one's folds."""
    body = "Base == {{{v}, 7}}\nStep(a) == a \\cup Base\nInit == x = Step({{1}}) /\\ y = Step({{1}}) /\\ z = Base\n" \
           "Next == UNCHANGED <<x, y, z>>"
    first = _write(tmp_path / "first", "Chain", body.format(v=5))
    second = _write(tmp_path / "second", "Chain", body.format(v=6))
    monkeypatch.setattr(Compiler, "fast_paths", True)
    assert load_model(str(first)).initial_states() == [(frozenset({1, 5, 7}),) * 2 + (frozenset({5, 7}),)]
    assert load_model(str(second)).initial_states() == [(frozenset({1, 6, 7}),) * 2 + (frozenset({6, 7}),)]


def test_a_failing_constant_is_reported_where_it_is_reached(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A constant whose evaluation fails is not memoised: an unreached site stays silent and
    the reached one reports the error at the same text and position as without folding."""
    tla = _write(tmp_path, "Failing", """
Ratio(a) == 10 \\div a
Init == /\\ x = IF TRUE THEN 1 ELSE Ratio(0)
        /\\ y = Ratio(5)
        /\\ z = 0
Next == /\\ x' = IF z = 0 THEN Ratio(0) ELSE 1
        /\\ UNCHANGED <<y, z>>""")
    fast = _observe(tla, True, monkeypatch)
    assert fast == _observe(tla, False, monkeypatch)
    assert fast == ("error", "module eval", "The second argument of \\div is 0.", f"{tla}:5:13")


def test_expansion_depth_limit_still_applies_to_a_memoised_constant(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A constant folded at a shallow site and met again deeper than the expansion depth
    limit is refused there as before (the memo does not skip the depth check of its
    expansion).  The limit, a guard for the Python stack (5000 nested definitions), is set
    to 60 here.  The action compiler compiles Init's conjuncts last first: D5(1) is folded
    before D61(1)."""
    from safestate.tla import actions, fold_memo
    from safestate.tla.compile import expansion
    for module in (fold_memo, expansion, actions):
        monkeypatch.setattr(module, "EXPANSION_LIMIT", 60)
    chain = "\n".join(f"D{i}(a) == D{i - 1}(a)" for i in range(1, 62))
    tla = _write(tmp_path, "Deep", f"""
D0(a) == a + 1
{chain}
Init == /\\ z = 0
        /\\ y = D61(1)
        /\\ x = D5(1)
Next == UNCHANGED <<x, y, z>>""")
    fast = _observe(tla, True, monkeypatch)
    assert fast == _observe(tla, False, monkeypatch)
    assert fast[0] == "load error" and "expanded at a depth of more than 60 nested definitions" in fast[2], fast
