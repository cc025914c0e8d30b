"""Parsing and evaluation of each supported construct (compared with TLC's values)."""

from __future__ import annotations

import pytest

from safestate.checker.model import load_model
from safestate.tla.errors import TlaError
from safestate.tla.values import FnValue, IntervalSet, ModelValue, fmt

SPEC = """---- MODULE Ev ----
EXTENDS Naturals, Integers, Sequences, FiniteSets, TLC, Bags
CONSTANTS N, Procs
VARIABLES x, y
RECURSIVE Fact(_)
Fact(n) == IF n = 0 THEN 1 ELSE n * Fact(n - 1)
fib[n \\in Nat] == IF n < 2 THEN n ELSE fib[n - 1] + fib[n - 2]
Twice(F(_), v) == F(F(v))
Inc(v) == v + 1
a ++ b == a + 2 * b
Init == x = 0 /\\ y = <<>>
Next == x' = x + 1 /\\ y' = Append(y, x)
====
"""
CFG = "CONSTANTS N = 3\n  Procs = {p1, p2}\nINIT Init\nNEXT Next\n"


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    d = tmp_path_factory.mktemp("ev")
    (d / "Ev.tla").write_text(SPEC)
    (d / "Ev.cfg").write_text(CFG)
    return load_model(str(d / "Ev.tla"))


CASES = [
    ("1 + 2 * 3", 7), ("7 \\div 2", 3), ("(-7) \\div 2", -4), ("-7 \\div 2", -3), ("-7 % 3", 2), ("2 ^ 10", 1024), ("-(3)", -3),
    ("3 > 2 /\\ 2 >= 2 /\\ 1 < 2 /\\ 1 <= 1", True), ("TRUE => FALSE", False), ("FALSE <=> FALSE", True),
    ("~TRUE \\/ 1 # 1", False), ("1 /= 2", True),
    ("{1, 2} \\cup {3}", frozenset({1, 2, 3})), ("{1, 2} \\cap {2}", frozenset({2})), ("{1, 2} \\ {1}", frozenset({2})),
    ("{1} \\subseteq {1, 2}", True), ("SUBSET {1, 2} = {{}, {1}, {2}, {1, 2}}", True),
    ("UNION {{1}, {2, 3}}", frozenset({1, 2, 3})), ("Cardinality(1..5)", 5), ("3 \\in Nat", True),
    ("-3 \\in Nat", False), ("-3 \\in Int", True), ("{x1 \\in 1..6 : x1 % 2 = 0}", frozenset({2, 4, 6})),
    ("{2 * i : i \\in 1..3}", frozenset({2, 4, 6})), ("{<<a, b>> \\in {1} \\X {2, 3} : b > 2}", frozenset({(1, 3)})),
    ("<<1, 2>> = [i \\in 1..2 |-> i]", True), ("[i \\in 1..3 |-> i * i][3]", 9), ("DOMAIN <<5, 6>>", IntervalSet(1, 2)),
    ("[r \\in {\"a\"} |-> 1] = [a |-> 1]", True), ("[a |-> 1, b |-> 2].b", 2),
    ("[[a |-> 1, b |-> 2] EXCEPT !.a = @ + 10].a", 11), ("[<<1, 2>> EXCEPT ![2] = 7]", (1, 7)),
    ("[f \\in [{1} -> {<<1, 2>>}] |-> 0] = [g \\in {[i \\in {1} |-> <<1, 2>>]} |-> 0]", True),
    ("[[a |-> <<1, 2>>] EXCEPT !.a[2] = 9].a", (1, 9)), ("[{1, 2} -> {0}] = {[i \\in {1, 2} |-> 0]}", True),
    ("[a : {1, 2}, b : {3}] = {[a |-> 1, b |-> 3], [a |-> 2, b |-> 3]}", True),
    ("Len(<<1, 2, 3>>)", 3), ("Head(<<4, 5>>)", 4), ("Tail(<<4, 5>>)", (5,)), ("<<1>> \\o <<2>>", (1, 2)),
    ("SubSeq(<<1, 2, 3, 4>>, 2, 3)", (2, 3)), ("SelectSeq(<<1, 2, 3, 4>>, LAMBDA e : e % 2 = 0)", (2, 4)),
    ("<<1, 2>> \\in Seq({1, 2})", True), ("\"ab\" \\o \"c\"", "abc"), ("Len(\"abc\")", 3),
    ("\\A i \\in 1..3 : i > 0", True), ("\\E i \\in 1..3 : i > 2", True), ("\\E i, j \\in 1..2 : i + j = 4", True),
    ("CHOOSE i \\in 1..10 : i * i > 20", 5), ("IF 1 > 2 THEN 1 ELSE 2", 2),
    ("CASE 1 > 2 -> 1 [] 2 > 1 -> 2 [] OTHER -> 3", 2), ("CASE FALSE -> 1 [] OTHER -> 3", 3),
    ("LET sq(v) == v * v  k == 3 IN sq(k)", 9), ("Fact(5)", 120), ("fib[10]", 55),
    ("Twice(Inc, 1)", 3), ("Twice(LAMBDA v : v * 3, 1)", 9), ("2 ++ 3", 8), ("N", 3),
    ("Procs", frozenset({ModelValue("p1"), ModelValue("p2")})), ("ModelValueCompare(1)", None),
    ("(1 :> 2) @@ (3 :> 4) = [i \\in {1, 3} |-> i + 1]", True), ("Permutations({1, 2}) = {<<1, 2>>, <<2, 1>>}", True),
    ("SortSeq(<<3, 1, 2>>, LAMBDA p, q : p < q)", (1, 2, 3)), ("ToString(<<1, \"a\">>)", '<<1, "a">>'),
    ("BagToSet(SetToBag({1, 2}) (+) SetToBag({2}))", frozenset({1, 2})), ("CopiesIn(2, SetToBag({2}) (+) SetToBag({2}))", 2),
    ("x + 1", 1), ("Len(y)", 0), ("\\X", None),
]


@pytest.mark.parametrize("expr,value", [c for c in CASES if c[1] is not None])
def test_checker_evaluates_construct_like_tlc(model, expr: str, value) -> None:
    got = model.eval_in_state(expr, (0, ()))
    assert got == value and type(got) is type(value) or fmt(got) == fmt(value), f"{expr} -> {fmt(got)}"


@pytest.mark.parametrize("expr,message", [
    ("1 + \"a\"", "non-integer"), ("1 = \"a\"", "equality"), ("<<1, 2>>[3]", "not in the domain"),
    ("CHOOSE i \\in 1..3 : i > 5", "no element of S satisfied P"), ("\\A i : i > 0", "non-enumerable"),
    ("CASE FALSE -> 1", "CASE"), ("Fact(1, 2)", "requires 1 arguments"), ("undefinedThing", "Unknown operator"),
    ("[a |-> 1].b", "nonexistent field"), ("3.5", "real number"), ("{i : i \\in Nat}", "infinite set"),
])
def test_checker_reports_evaluation_errors_with_position(model, expr: str, message: str) -> None:
    with pytest.raises(TlaError) as err:
        model.eval_in_state(expr, (0, ()))
    assert message in err.value.message
    assert err.value.loc is not None and err.value.loc.line >= 1


@pytest.mark.parametrize("expr,printed", [("{} \\cup 0..2", "0..2"), ("(1..0) \\cup 0..2", "0..2"),
                                          ("0..2 \\cup {}", "{0, 1, 2}"), ("{1} \\cup 0..2", "{0, 1, 2}")])
def test_checker_prints_a_union_with_the_empty_set_as_tlc(model, expr: str, printed: str) -> None:
    """TLC returns S itself for `{} \\cup S`, so a trace shows `0..2` (difftest seed 5151,
    spec 1066: a deadlock trace), but a non-empty interval's union is enumerated."""
    assert fmt(model.eval_in_state(expr, (0, ()))) == printed


def test_checker_choose_and_printing_follow_tlc_string_order(model) -> None:
    # TLC orders strings by first appearance, not alphabetically.
    assert model.eval_in_state('CHOOSE s \\in {"zz", "aa"} : TRUE', None) in ("zz", "aa")
    assert fmt(model.eval_in_state("{<<2, 1>>, <<1, 2, 3>>, <<1, 5>>}", None)) == "{<<1, 5>>, <<2, 1>>, <<1, 2, 3>>}"
    assert fmt(model.eval_in_state("{{3}, {1, 2}, {0}}", None)) == "{{0}, {3}, {1, 2}}"


def test_checker_records_are_functions_over_strings(model) -> None:
    r = model.eval_in_state('[a |-> 1, b |-> "x"]', None)
    assert isinstance(r, FnValue) and r.d == {"a": 1, "b": "x"}


def test_checker_successors_carry_action_and_params(tla_dir) -> None:
    path = tla_dir("Act", """---- MODULE Act ----
EXTENDS Naturals
CONSTANT P
VARIABLE c
Init == c = [p \\in P |-> 0]
Inc(p) == c[p] < 2 /\\ c' = [c EXCEPT ![p] = @ + 1]
Reset == (\\A p \\in P : c[p] = 2) /\\ c' = [p \\in P |-> 0]
Next == (\\E p \\in P : Inc(p)) \\/ Reset
====
""", "CONSTANT P = {1, 2}\nINIT Init\nNEXT Next\n")
    m = load_model(str(path))
    (s0,) = m.initial_states()
    trs = m.successors(s0)
    assert [(t.action, t.params) for t in trs] == [("Inc", {"p": 1}), ("Inc", {"p": 2})]
    assert m.invariant_violations(s0) == []
    assert m.state_from_itf(m.state_to_itf(s0)) == s0


def test_checker_instance_with_substitution_and_parameterised_instance(tla_dir) -> None:
    tla_dir("Counter", """---- MODULE Counter ----
EXTENDS Naturals
CONSTANT Max
VARIABLE n
Step == n < Max /\\ n' = n + 1
Ok == n <= Max
====
""")
    path = tla_dir("Top", """---- MODULE Top ----
EXTENDS Naturals
VARIABLES a, b
A == INSTANCE Counter WITH n <- a, Max <- 2
B(m) == INSTANCE Counter WITH n <- b, Max <- m
INSTANCE Counter WITH n <- a, Max <- 5
Init == a = 0 /\\ b = 0
Next == (A!Step /\\ UNCHANGED b) \\/ (B(3)!Step /\\ UNCHANGED a)
Inv == A!Ok /\\ B(3)!Ok /\\ Ok
====
""", "INIT Init\nNEXT Next\nINVARIANT Inv\nCHECK_DEADLOCK FALSE\n")
    from safestate.checker.explore import explore_states
    r = explore_states(load_model(str(path)))
    assert (r.result, r.distinct_states, r.depth) == ("success", 12, 6)


def test_checker_unassigned_variable_is_an_error_like_tlc(tla_dir) -> None:
    path = tla_dir("Part", "---- MODULE Part ----\nVARIABLES x, y\nInit == x = 0 /\\ y = 0\nNext == x' = 1\n====\n",
                   "INIT Init\nNEXT Next\n")
    from safestate.checker.explore import explore_states
    r = explore_states(load_model(str(path)))
    assert r.result == "error" and "not completely specified" in r.error.message
