"""Recursion: a depth TLC handles is checked; one that never ends is TLC's
StackOverflowError -- a one-line error and TLC's exit code, never a traceback."""

from __future__ import annotations

import pytest

from conftest import run_safestate
from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla.errors import TlaError

SPEC = """---- MODULE Rec ----
EXTENDS Naturals
VARIABLE x
RECURSIVE F(_)
F(n) == IF n = 0 THEN 0 ELSE 1 + F(n - 1)
Init == x = {init}
Next == x' = {next}
====
"""


@pytest.mark.parametrize("where", ["init", "next"])
def test_recursion_two_thousand_deep_is_checked(where: str, tla_dir) -> None:
    init, nxt = ("F(2000)", "x") if where == "init" else ("0", "F(2000) % 2")
    path = tla_dir("Rec", SPEC.format(init=init, next=nxt), "INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(path))
    assert p.returncode == 0, p.stdout + p.stderr


@pytest.mark.parametrize("where, code", [("init", 75), ("next", 255)])
def test_endless_recursion_is_a_clear_error_with_tlc_exit_code(where: str, code: int, tla_dir) -> None:
    init, nxt = ("F(10000000)", "x") if where == "init" else ("0", "F(10000000)")
    path = tla_dir("Rec", SPEC.format(init=init, next=nxt), "INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(path))
    out = p.stdout + p.stderr
    assert p.returncode == code, out
    assert "recursion too deep" in out and "StackOverflowError" in out
    assert "Traceback" not in out and "internal error" not in out


# Recursive operators that build sequences and sets, recurse through an operator
# argument (LAMBDA) and a CONSTANT operator (Op <- Tri), and read state: under a prime
# (Sum(n)'), in Init, and with a primed argument.  TLC 1.8.0: 22 states generated,
# 22 distinct, depth 4, no error.
RECURSIVE_FORMS = """---- MODULE RecForms ----
EXTENDS Naturals, Sequences, FiniteSets
CONSTANT Op(_)
VARIABLE log, total
RECURSIVE Sum(_)
Sum(i) == IF i = 0 THEN 0 ELSE log[i] + Sum(i - 1)
RECURSIVE Tri(_)
Tri(n) == IF n = 0 THEN 0 ELSE n + Tri(n - 1)
RECURSIVE Rev(_)
Rev(s) == IF s = <<>> THEN <<>> ELSE Rev(Tail(s)) \\o <<Head(s)>>
RECURSIVE Upto(_)
Upto(n) == IF n = 0 THEN {} ELSE {n} \\cup Upto(n - 1)
RECURSIVE Map(_, _)
Map(F(_), s) == IF s = <<>> THEN <<>> ELSE <<F(Head(s))>> \\o Map(F, Tail(s))
Init == log \\in {<<1>>, <<2, 1>>} /\\ total = Sum(Len(log))
Next == \\E k \\in Upto(2) :
          /\\ Len(log) < 4
          /\\ log' = Rev(Append(log, Op(k)))
          /\\ total' = total + Op(k)
          /\\ Sum(Len(log))' = total'
          /\\ Map(LAMBDA v : v + 1, log)' = [i \\in 1..Len(log') |-> log'[i] + 1]
Inv == total = Sum(Len(log))
====
"""
RECURSIVE_FORMS_CFG = "CONSTANT Op <- Tri\nINIT Init\nNEXT Next\nINVARIANT Inv\nCHECK_DEADLOCK FALSE\n"


def test_recursive_operators_building_sequences_and_sets_through_constants_and_primes_match_tlc(tla_dir) -> None:
    path = tla_dir("RecForms", RECURSIVE_FORMS, RECURSIVE_FORMS_CFG)
    r = explore_states(load_model(str(path)))
    assert (r.result, r.states_generated, r.distinct_states, r.depth) == ("success", 22, 22, 4)


def test_recursive_operator_with_primed_argument_reads_the_current_state_like_tlc(tla_dir) -> None:
    # TLC evaluates Sum(Len(log')) with log[i] in the current state: index 2 of <<3>>
    # is out of bounds after 2 states generated, 2 distinct (exit 75).
    spec = RECURSIVE_FORMS.replace("/\\ Sum(Len(log))' = total'", "/\\ Sum(Len(log')) = total'")
    path = tla_dir("RecForms", spec.replace("<<2, 1>>", "<<3>>"), RECURSIVE_FORMS_CFG)
    r = explore_states(load_model(str(path)))
    assert (r.result, r.error.kind if r.error else None) == ("error", "eval")
    assert (r.states_generated, r.distinct_states) == (2, 2)


def test_endless_recursion_in_an_assumption_is_tlc_stack_overflow(tla_dir) -> None:
    spec = SPEC.format(init="0", next="x").replace("Init ==", "ASSUME F(10000000) > 0\nInit ==")
    p = run_safestate("check", str(tla_dir("Rec", spec, "INIT Init\nNEXT Next\n")))
    out = p.stdout + p.stderr
    assert p.returncode == 255, out  # TLC: "This was a Java StackOverflowError", exit 255
    assert "StackOverflowError" in out and "internal error" not in out and "Traceback" not in out


def test_recursive_action_level_operator_is_checked_by_descending_into_it(tla_dir) -> None:
    """Step(k) primes x at the bottom of its recursion; TLC evaluates it as an action
    at each call (the corpus spec RecursiveAction compares counts and trace with TLC)."""
    spec = SPEC.format(init="0", next="x + 1").replace(
        "Init ==", "RECURSIVE Step(_)\nStep(k) == IF k = 0 THEN x' = (x + 1) % 3 ELSE Step(k - 1)\nInit ==")
    r = explore_states(load_model(str(tla_dir("Rec", spec.replace("Next == x' = x + 1", "Next == Step(2)"),
                                              "INIT Init\nNEXT Next\n"))))
    assert (r.result, r.distinct_states, r.states_generated, r.depth) == ("success", 3, 4, 3)


def test_recursive_operator_priming_its_parameter_is_refused_with_its_position(tla_dir) -> None:
    """TLC binds a primed parameter by name (`q'` is the variable passed); a recursive
    call passes values, so this is refused rather than guessed at."""
    spec = SPEC.format(init="0", next="x + 1").replace(
        "Init ==", "RECURSIVE Step(_, _)\nStep(q, k) == IF k = 0 THEN q' = 1 ELSE Step(q, k - 1)\nInit ==")
    with pytest.raises(TlaError) as e:
        load_model(str(tla_dir("Rec", spec.replace("Next == x' = x + 1", "Next == Step(x, 2)"),
                               "INIT Init\nNEXT Next\n")))
    assert e.value.kind == "unsupported" and "Step primes one of its parameters" in e.value.message
    assert e.value.loc is not None and e.value.loc.line == 9  # the call in Next
