"""The checker's fast paths (constant folding, inlining, specialised closures,
batched EXCEPT, assignment runs) give exactly the results of the general closures.

Each spec is checked twice, with `Compiler.fast_paths` on and off, and everything
observable is compared: verdict, counts, depth, trace, successors, values, and
the text and position of evaluation errors.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla.compiler import Compiler
from safestate.tla.errors import TlaError

CORPUS = Path(__file__).resolve().parents[1] / "tla" / "corpus"

# Constant pieces, small operators called with slots / constants / expressions,
# records updated by multi-field EXCEPT with @, tuples updated by index, IF
# chains with constant and non-constant branches, CASE tables, UNCHANGED runs
# where a later right-hand side reads an earlier primed variable, % and \div.
SPEC = """---- MODULE Fast ----
EXTENDS Naturals, Integers, Sequences, FiniteSets
CONSTANTS N, Procs
VARIABLES r, q, n, pc, log
Colours == {"red", "green", "blue"}
Lim == N + 1
NoRec == [a |-> 0, b |-> "x", c |-> <<>>]
IsRed(c) == c = "red"
Bump(m, k) == [m EXCEPT !.a = (@ + k) % Lim, !.b = IF @ = "x" THEN "y" ELSE "x", !.c = IF Len(@) < 3 THEN Append(@, k) ELSE <<>>]
Row(m) == IF m.a = 0 THEN "zero" ELSE IF m.a = 1 THEN "one" ELSE IF m.a > 5 THEN "big" ELSE "some"
Val(m) == IF m.a = 0 THEN m.a ELSE IF m.a = 1 THEN m.a * 10 ELSE m.a + N
Step(p) == CASE p = "a" -> "b" [] p = "b" -> "c" [] p = "c" -> "a"
Init == /\\ r = NoRec /\\ q = <<0, 0, 0>> /\\ n = 0 /\\ pc = "a" /\\ log = <<>>
Move(k) == /\\ k \\in 1..N
           /\\ r' = Bump(r, k)
           /\\ q' = [q EXCEPT ![k] = (@ + 1) % 3, ![4] = 99, ![1] = r'.a]
           /\\ n' = (n + k) \\div 2
           /\\ pc' = Step(pc)
           /\\ log' = IF Len(log) < 2 THEN Append(log, Row(r')) ELSE log
Idle == /\\ IsRed("red") /\\ "red" \\in Colours /\\ n \\notin {7, 8}
        /\\ n' = Val(r) % 3
        /\\ UNCHANGED <<r, q, pc>> /\\ log' = log
Next == (\\E k \\in 1..N : Move(k)) \\/ Idle
TypeOK == /\\ r \\in [a : 0..Lim, b : {"x", "y"}, c : Seq(1..N)]
          /\\ pc \\in {"a", "b", "c"} /\\ n \\in Int /\\ Len(r.c) < 4
====
"""
CFG = "CONSTANTS N = 3\n  Procs = {p1, p2}\nINIT Init\nNEXT Next\nINVARIANT TypeOK\n"

# Evaluation errors must be reported identically (text and position).
ERROR_SPECS = {
    "mod0": "x' = x % (x - x)",
    "div0": "x' = x \\div (x - x)",
    "field": "x' = [a |-> 1].b",
    "eqkind": "x' = IF x = \"s\" THEN 1 ELSE 2",
    "nonrec": "x' = x.f",
    "case": "x' = CASE x = 5 -> 1 [] x = 6 -> 2",
    "unset": "x' = x' + 1",
    "lazyerr": "x' = LET F(a) == a + 1 IN F(\"s\")",
}


def _check(tla: Path, cfg: Path | None, fast: bool, monkeypatch: pytest.MonkeyPatch,
           switch: str = "fast_paths") -> tuple:
    """Everything observable of checking `tla` with the Compiler's `switch` on or off."""
    monkeypatch.setattr(Compiler, switch, fast)
    try:
        model = load_model(str(tla), str(cfg) if cfg else None)
        r = explore_states(model)
    except TlaError as e:
        return ("load error", e.kind, e.message, str(e.loc))
    err = (r.error.kind, r.error.message, str(r.error.loc)) if r.error else None
    trace = [(s.state, s.action, s.params) for s in r.trace] if r.trace else None
    try:
        succ = [(tr.action, tr.params, tr.state) for st in model.initial_states() for tr in model.successors(st)]
    except TlaError as e:
        succ = [(e.kind, e.message, str(e.loc))]
    return (r.result, r.distinct_states, r.states_generated, r.depth, r.violated, err, trace, succ)


def test_fast_paths_equal_general_paths(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "Fast.tla").write_text(SPEC)
    (tmp_path / "Fast.cfg").write_text(CFG)
    fast = _check(tmp_path / "Fast.tla", None, True, monkeypatch)
    slow = _check(tmp_path / "Fast.tla", None, False, monkeypatch)
    assert fast == slow
    assert fast[0] == "success" and fast[1] > 10


def test_fast_paths_values(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "Fast.tla").write_text(SPEC)
    (tmp_path / "Fast.cfg").write_text(CFG)
    exprs = ["Bump(NoRec, 2)", "Row([a |-> 7])", "Val([a |-> 1])", "Step(\"c\")", "Lim * 2 - 1",
             "[q EXCEPT ![2] = 5, ![2] = @ * 3]", "[NoRec EXCEPT !.zz = 1]", "-7 % 3", "(-7) \\div 2"]
    out = {}
    for fast in (True, False):
        monkeypatch.setattr(Compiler, "fast_paths", fast)
        model = load_model(str(tmp_path / "Fast.tla"))
        init = model.initial_states()[0]
        out[fast] = [model.eval_in_state(x, init) for x in exprs]
    assert out[True] == out[False]


@pytest.mark.parametrize("name", sorted(ERROR_SPECS))
def test_fast_paths_errors(name: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    spec = f"---- MODULE E ----\nEXTENDS Naturals\nVARIABLE x\nInit == x = 3\nNext == {ERROR_SPECS[name]}\n====\n"
    (tmp_path / "E.tla").write_text(spec)
    (tmp_path / "E.cfg").write_text("INIT Init\nNEXT Next\n")
    fast = _check(tmp_path / "E.tla", None, True, monkeypatch)
    slow = _check(tmp_path / "E.tla", None, False, monkeypatch)
    assert fast[:6] == slow[:6]
    assert fast[0] in ("error", "load error")


@pytest.mark.parametrize("name", ["TwoPhase", "FunctionsRecords", "Peterson", "TrafficView", "SetOps",
                                  "Operators", "VendingMachine"])
def test_fast_paths_on_corpus(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    tla, cfg = CORPUS / f"{name}.tla", CORPUS / f"{name}.cfg"
    assert _check(tla, cfg, True, monkeypatch)[:7] == _check(tla, cfg, False, monkeypatch)[:7]
