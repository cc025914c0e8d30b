"""Issue 27, item 0: operator arguments are passed unevaluated, as TLC passes them.
An argument the body never reaches is never evaluated (no error where TLC finds
none), in both engines; one the body does reach fails where TLC fails, at the
argument's own position."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import CORPUS, load_expected, run_safestate

EXPECTED = load_expected(CORPUS)


@pytest.mark.parametrize("engine,name", [
    ("python", "LazyOperatorArguments"), ("native", "LazyOperatorArguments"),
    ("python", "LazyRecursiveArguments"),
])
def test_an_argument_the_body_does_not_reach_is_not_evaluated(engine: str, name: str) -> None:
    p = run_safestate("check", str(CORPUS / f"{name}.tla"), "--engine", engine, "--json")
    got, want = json.loads(p.stdout), EXPECTED[name]
    assert "not supported by the native engine" not in p.stderr
    assert "checking again with the Python engine" not in p.stderr  # the core itself found no error
    for f in ("result", "distinct_states", "states_generated", "depth", "violated"):
        assert got[f] == want[f], f"{f}: ours {got[f]!r}, TLC {want[f]!r}"
    assert p.returncode == want["exit_code"]


SPEC = """---- MODULE Reached ----
EXTENDS Naturals
VARIABLE x
Msgs == {[method |-> "join", dest |-> 1], [method |-> "join"]}
Guarded(d, m) == m.method = "join" => d \\in 1..2
Init == x = 0
Next == x' = x
Inv == \\A m \\in Msgs : Guarded(m.dest, m)
====
"""


@pytest.mark.parametrize("engine", ["python", "native"])
def test_an_argument_the_body_reaches_fails_at_its_own_position(engine: str, tmp_path: Path) -> None:
    # The second message is a join without `dest`: the body reads d, TLC reports the error.
    tla = tmp_path / "Reached.tla"
    tla.write_text(SPEC)
    (tmp_path / "Reached.cfg").write_text("INIT Init\nNEXT Next\nINVARIANT Inv\n")
    p = run_safestate("check", str(tla), "--engine", engine, "--json")
    got = json.loads(p.stdout)
    assert p.returncode == 75
    assert got["result"] == "error"
    assert "nonexistent field 'dest'" in got["error"]["message"]
    assert (got["error"]["line"], got["error"]["column"]) == (8, 32)  # m.dest


@pytest.mark.parametrize("engine", ["python", "native"])
def test_an_instance_operator_gets_its_arguments_unevaluated(engine: str, tmp_path: Path) -> None:
    (tmp_path / "G.tla").write_text('---- MODULE G ----\nEXTENDS Naturals\n'
                                    'Targeted(d, m) == m.method = "join" => d \\in 1..2\n====\n')
    (tmp_path / "InstLazy.tla").write_text(
        '---- MODULE InstLazy ----\nVARIABLE x\nI == INSTANCE G\n'
        'Msgs == {[method |-> "join", dest |-> 1], [method |-> "leave"]}\n'
        'Init == x = 0\nNext == x\' = x\nInv == \\A m \\in Msgs : I!Targeted(m.dest, m)\n====\n')
    (tmp_path / "InstLazy.cfg").write_text("INIT Init\nNEXT Next\nINVARIANT Inv\n")
    p = run_safestate("check", str(tmp_path / "InstLazy.tla"), "--engine", engine, "--json")
    got = json.loads(p.stdout)
    assert (got["result"], got["distinct_states"], got["states_generated"], got["depth"]) == ("success", 1, 2, 1)
    assert p.returncode == 0
