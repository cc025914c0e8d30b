"""Issue 32: the native core evaluates TLC's ToString itself, printing every kind of
value as TLC prints it (the Python engine's `values.fmt` is the reference); where the
core cannot know TLC's printed form (a set TLC keeps as a rule, ``1..3``, ``[a : S]``)
it refuses the spec with the position, and ``--engine auto`` gives the Python engine's
result."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import run_safestate
from native_engines import assert_cli_engines_agree, assert_engines_agree, write_spec
from safestate.checker.model import load_model
from safestate.checker.native.search import native_unsupported

# Every value kind, nested: strings with escapes, records, functions of other keys,
# sequences, sets of integers (consecutive ones too, built element by element).
EVERY_KIND = r"""EXTENDS Integers, Sequences, TLC
CONSTANT M
VARIABLES x, y, s
Init == /\ x = 0 /\ s = ""
        /\ y = <<"a\"b\\c", [k |-> {TRUE}, a |-> M], (1 :> "q") @@ (3 :> FALSE), <<>>, {}, -2>>
Next == /\ x < 5 /\ x' = x + 1 /\ y' = Append(y, {x, 2}) /\ s' = ToString(y)
Inv == s # ToString(<<"a\"b\\c", [k |-> {TRUE}, a |-> M], (1 :> "q") @@ (3 :> FALSE), <<>>, {}, -2, {0, 2},
                      {1, 2}, {2}>>)
"""


def test_tostring_of_every_value_kind_is_tlcs_in_the_core(tmp_path: Path) -> None:
    tla = write_spec(tmp_path, "EveryKind", EVERY_KIND, "CONSTANT M = m\nINIT Init\nNEXT Next\nINVARIANT Inv\n")
    r = assert_engines_agree(tla)
    assert r.result == "safety failure" and r.depth == 5  # the printed forms met: the invariant fails
    assert r.trace is not None
    assert r.trace[-1].state[2] == ('<<"a\\"b\\\\c", [k |-> {TRUE}, a |-> m], (1 :> "q" @@ 3 :> FALSE), <<>>, {}, '
                                    '-2, {0, 2}, {1, 2}, {2}>>')
    assert assert_cli_engines_agree(tla) == 12


def test_tostring_results_with_two_workers_are_the_one_workers(tmp_path: Path) -> None:
    tla = write_spec(tmp_path, "EveryKind", EVERY_KIND, "CONSTANT M = m\nINIT Init\nNEXT Next\nINVARIANT Inv\n")
    one = assert_engines_agree(tla)
    two = assert_engines_agree(tla, workers=2)
    assert (two.result, two.distinct_states, two.depth) == (one.result, one.distinct_states, one.depth)


def test_tostring_strings_are_values_the_search_compares(tmp_path: Path) -> None:
    # Strings made by ToString are states' values: equal strings are one state.
    tla = write_spec(tmp_path, "Made", "EXTENDS Naturals, TLC\nVARIABLES n, s\n"
                     "Init == n = 0 /\\ s = \"0\"\n"
                     "Next == n' = (n + 1) % 3 /\\ s' = ToString(n' % 2)\n"
                     "NotTuple(t) == t # ToString(<<n>>)\nInv == s \\in {\"0\", \"1\"} /\\ NotTuple(s)\n",
                     "INIT Init\nNEXT Next\nINVARIANT Inv\n")
    r = assert_engines_agree(tla)
    assert (r.result, r.distinct_states) == ("success", 3)
    assert assert_cli_engines_agree(tla) == 0


@pytest.mark.parametrize("arg,where", [
    ("1..x", "a range"),
    ("DOMAIN <<x, x>>", "the domain of a sequence"),
    ("[a : {x}]", "a set of records"),
    ("<<{}, r>>", "a variable that holds a range"),
    ("{} \\cup r", "a union that may be its operand"),
])
def test_tostring_of_a_set_tlc_prints_as_a_rule_is_refused_with_its_position(
        arg: str, where: str, tmp_path: Path) -> None:
    tla = write_spec(tmp_path, "Rule", "EXTENDS Naturals, TLC\nVARIABLES x, r, s\n"
                     "Init == x = 1 /\\ r = 1..2 /\\ s = \"\"\n"
                     f"Next == x' = 1 + (x % 3) /\\ r' = r /\\ s' = ToString({arg})\n",
                     "INIT Init\nNEXT Next\n")
    refusal = native_unsupported(load_model(tla))
    assert refusal is not None, where
    assert "ToString" in refusal.message and "not supported by the native engine" in refusal.message
    assert refusal.loc is not None and refusal.loc.line == 5
    native = run_safestate("check", tla, "--engine", "native")
    assert native.returncode != 0 and "Rule.tla:5:" in native.stderr and "Traceback" not in native.stderr
    auto = run_safestate("check", tla, "--engine", "auto", "--json")
    python = run_safestate("check", tla, "--engine", "python", "--json")
    assert auto.returncode == python.returncode == 0
    assert "using the Python engine" in auto.stderr and len(auto.stderr.strip().splitlines()) == 1
    assert json.loads(auto.stdout)["distinct_states"] == json.loads(python.stdout)["distinct_states"]


def test_a_trace_prints_a_range_held_in_a_state_as_tlc_does(tmp_path: Path) -> None:
    # The core holds 1..n by its elements; the trace shows TLC's 1..n, as the Python engine's.
    tla = write_spec(tmp_path, "Ranges", "EXTENDS Naturals\nVARIABLES n, r, d\n"
                     "Init == n = 1 /\\ r = 1..1 /\\ d = {}\n"
                     "Next == n < 4 /\\ n' = n + 1 /\\ r' = 1..n' /\\ d' = DOMAIN <<n, n>> \\cup {}\n"
                     "Inv == n < 3\n", "INIT Init\nNEXT Next\nINVARIANT Inv\n")
    r = assert_engines_agree(tla)
    assert r.trace is not None and len(r.trace) == 3
    native = run_safestate("check", tla, "--engine", "native")
    python = run_safestate("check", tla, "--engine", "python")
    assert native.returncode == python.returncode == 12
    assert "/\\ r = 1..3" in native.stdout and "/\\ d = {1, 2}" in native.stdout  # TLC prints both so
    strip = lambda out: [x for x in out.splitlines() if not x.startswith("Finished")]  # noqa: E731
    assert strip(native.stdout) == strip(python.stdout)
