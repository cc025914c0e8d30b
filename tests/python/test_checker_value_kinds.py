"""Issue 27 item 1: TRUE and 1, FALSE and 0 are different values (Python's ``True ==
1`` and ``hash(True) == hash(1)`` must not leak into TLA+): in the state table,
records, functions, sets and sequences, and in the memo tables; and where TLC refuses
to compare values of incomparable kinds (``1 \\in BOOLEAN``, ``{1, TRUE}``, ``<<1>> =
<<TRUE>>``), its error (exit 75) with its message, not an answer.

One spec per class, with TLC's figures (TLC 1.8.0, ``-workers 1``, recorded here as
data), checked with both engines wherever the native core accepts the spec."""

from __future__ import annotations

import json
from typing import NamedTuple

import pytest

from conftest import run_safestate


class Tlc(NamedTuple):
    exit_code: int
    distinct: int
    generated: int
    depth: int
    message: str | None  # TLC's error message (its first two lines), for an error


class Case(NamedTuple):
    what: str
    body: str
    cfg_extra: str
    tlc: Tlc


CASES = {
    'KindStateMerge': Case(
        'the states x = 1 and x = TRUE, x = 0 and x = FALSE are four states',
        "VARIABLE x\nInit == x = 1\nNext == x' = TRUE \\/ x' = 1 \\/ x' = 0 \\/ x' = FALSE",
        '',
        Tlc(0, 4, 17, 2, None)),
    'KindToString': Case(
        'v = TRUE is a state of its own: ToString(v) sees "TRUE"',
        'VARIABLE v\nInit == v = 1\nNext == v\' = TRUE\nInv == ToString(v) # "TRUE"',
        'INVARIANT Inv\n',
        Tlc(12, 2, 2, 2, None)),
    'KindRecord': Case(
        '[val |-> FALSE] and [val |-> 0] are different records',
        "VARIABLE r\nInit == r = [val |-> 0]\n"
        "Next == r' = [val |-> FALSE] \\/ r' = [val |-> 0] \\/ r' = [val |-> TRUE] \\/ r' = [val |-> 1]",
        '',
        Tlc(0, 4, 17, 2, None)),
    'KindFunctionSet': Case(
        '[BOOLEAN -> {0}] and [0..1 -> {0}] hold different functions',
        "VARIABLE f\nInit == f \\in [0..1 -> {0}]\nNext == f' \\in [BOOLEAN -> {0}] \\/ f' \\in [0..1 -> {0}]",
        '',
        Tlc(0, 2, 5, 2, None)),
    'KindSet': Case(
        '{0} and {FALSE} are different sets',
        "VARIABLE s\nInit == s = {0}\nNext == s' = {FALSE} \\/ s' = {0} \\/ s' = {1} \\/ s' = {TRUE}",
        '',
        Tlc(0, 4, 17, 2, None)),
    'KindSequence': Case(
        '<<TRUE, FALSE>>, <<1, FALSE>> and <<1, 0>> are three sequences',
        "VARIABLE q\nInit == q = <<1, 0>>\nNext == q' = <<TRUE, FALSE>> \\/ q' = <<1, FALSE>> \\/ q' = <<1, 0>>",
        '',
        Tlc(0, 3, 10, 2, None)),
    'KindNotinBoolean': Case(
        "1 \\notin BOOLEAN compares an integer with booleans: TLC's error, not a violation",
        "VARIABLE v\nInit == v = 1\nNext == v' = v\nInv == v \\notin BOOLEAN",
        'INVARIANT Inv\n',
        Tlc(75, 1, 1, 1, 'Attempted to compare integer 1 with non-integer:\nTRUE')),
    'KindMemo': Case(
        'a memoised operator: F(TRUE) is not the answer kept for F(1)',
        'VARIABLES b, x\nF(a) == {y \\in {a} : TRUE}\nInit == b = FALSE /\\ x = F(1)\n'
        'Next == b\' = TRUE /\\ x\' = F(IF b\' THEN TRUE ELSE 1)\nInv == b => ToString(x) = "{TRUE}"',
        'INVARIANT Inv\n',
        Tlc(0, 2, 3, 2, None)),
    'KindSetLiteral': Case(
        '{1, TRUE} is an error, not a one-element set',
        "VARIABLE v\nInit == v = 0\nNext == v' = IF {1, TRUE} = {} THEN 1 ELSE 2\n",
        '',
        Tlc(75, 1, 1, 1, 'Attempted to compare boolean TRUE with non-boolean:\n1')),
    'KindEquality': Case(
        'v = TRUE with v = 1 is an error, not FALSE',
        "VARIABLE v\nInit == v = 1\nNext == v' = IF v = TRUE THEN 0 ELSE 1",
        '',
        Tlc(75, 1, 1, 1, 'Attempted to check equality of integer 1 with non-integer:\nTRUE')),
    'KindTupleEquality': Case(
        '<<1>> # <<TRUE>> is an error at any depth, not FALSE',
        "VARIABLE v\nInit == v = <<1>>\nNext == v' = v\nInv == v # <<TRUE>>",
        'INVARIANT Inv\n',
        Tlc(75, 1, 1, 1, 'Attempted to check equality of integer 1 with non-integer:\nTRUE')),
    'KindUnion': Case(
        '{1} \\cup {TRUE} is an error',
        "VARIABLE v\nInit == v = {1} \\cup {TRUE}\nNext == v' = v",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of integer 1 with non-integer:\nTRUE')),
    'KindFnApply': Case(
        '[b \\in BOOLEAN |-> 5][1] is an error, not 5',
        "VARIABLE v\nInit == v = 0\nNext == v' = [b \\in BOOLEAN |-> 5][1]",
        '',
        Tlc(75, 1, 1, 1, 'Attempted to compare integer 1 with non-integer:\nTRUE')),
    # Membership (TLC 1.8.0's exit codes and counts).  Where the message is None, TLC looks
    # a value up in a set literal by `equals` in the literal's order ("Attempted to check
    # equality of ..."), ours by its binary search ("Attempted to compare ..."): the same
    # exit code and counts, another first line (docs/tla-subset.md, Known differences).
    'KindTupleMember': Case(
        '<<TRUE>> \\in {<<1>>} is an error, not TRUE',
        "VARIABLE x\nInit == x = IF <<TRUE>> \\in {<<1>>} THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, None)),
    'KindSetMember': Case(
        '{1} \\in {{TRUE}} is an error, not TRUE',
        "VARIABLE x\nInit == x = IF {1} \\in {{TRUE}} THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, None)),
    'KindTupleMemberFalse': Case(
        '<<2>> \\in {<<TRUE>>} is an error, not FALSE',
        "VARIABLE x\nInit == x = IF <<2>> \\in {<<TRUE>>} THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, None)),
    'KindRecordMember': Case(
        '[a |-> TRUE] \\in {[a |-> 1]} is an error, not TRUE',
        "VARIABLE x\nInit == x = IF [a |-> TRUE] \\in {[a |-> 1]} THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, None)),
    'KindSubseteq': Case(
        '{TRUE} \\subseteq {1, 2} is an error, not FALSE',
        "VARIABLE x\nInit == x = IF {TRUE} \\subseteq {1, 2} THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, None)),
    'KindIntervalMember': Case(
        'TRUE \\in 1..3 is an error, not FALSE',
        "VARIABLE x\nInit == x = IF TRUE \\in 1..3 THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check if the value:\nTRUE')),
    'KindNatMember': Case(
        'TRUE \\in Nat is an error, not FALSE',
        "VARIABLE x\nInit == x = IF TRUE \\in Nat THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check if the value:\nTRUE')),
    'KindIntMember': Case(
        'TRUE \\in Int is an error, not FALSE',
        "VARIABLE x\nInit == x = IF TRUE \\in Int THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check if the value:\nTRUE')),
    'KindStringMember': Case(
        '1 \\in STRING is an error, not FALSE',
        "VARIABLE x\nInit == x = IF 1 \\in STRING THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check if the value:\n1')),
    'KindTupleMemberDecidedEarly': Case(
        '<<1, TRUE>> \\in {<<2, 3>>}: TLC decides at 1 < 2 and never compares TRUE with 3',
        "VARIABLE x\nInit == x = IF <<1, TRUE>> \\in {<<2, 3>>} THEN 1 ELSE 0\nNext == UNCHANGED x",
        '',
        Tlc(0, 1, 2, 1, None)),
    'KindRecordFunctionSet': Case(
        '{[val |-> 1], (2 :> 1)} is an error: sorting compares the field name with 2',
        "VARIABLE x\nInit == x = Cardinality({[val |-> 1], (2 :> 1)})\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to compare integer 2 with non-integer:\n"val"')),
    'KindSetsOfSetsSorted': Case(
        '{{1}, {"a"}} is an error (Python would not merge them: nothing to see without sorting)',
        "VARIABLE x\nInit == x = Cardinality({{1}, {\"a\"}})\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to compare string "a" with non-string:\n1')),
    'KindRecordFieldsSorted': Case(
        '{[a |-> {1}], [a |-> {"x"}]} is an error deep inside a field',
        "VARIABLE x\nInit == x = Cardinality({[a |-> {1}], [a |-> {\"x\"}]})\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to compare string "x" with non-string:\n1')),
    'KindRecordCupFunction': Case(
        '{[a |-> 1]} \\cup {(2 :> 1)} is an error: a record equals only what can be a record',
        "VARIABLE x\nInit == x = Cardinality({[a |-> 1]} \\cup {(2 :> 1)})\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of record:\n[a |-> 1]\nwith non-record\n(2 :> 1)')),
    'KindRecordEqualsFunction': Case(
        '[a |-> 1, b |-> 2] = (2 :> 1) is an error whatever the sizes, not FALSE',
        "VARIABLE x\nInit == x = ([a |-> 1, b |-> 2] = (2 :> 1))\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of record:\n[a |-> 1, b |-> 2]\nwith non-record\n(2 :> 1)')),
    'KindRecordEqualsEmptyTuple': Case(
        '[a |-> 1] = <<>> is FALSE: <<>> is also the empty record',
        "VARIABLE x\nInit == x = ([a |-> 1] = <<>>)\nNext == UNCHANGED x",
        '',
        Tlc(0, 1, 2, 1, None)),
    'KindComparableShapes': Case(
        'sets of compounds whose comparisons stop before kinds differ are sets: '
        '{[a |-> 1], [b |-> TRUE]}, {(1 :> 1 @@ 2 :> TRUE), (1 :> 2 @@ 3 :> 1)}, {{<<1>>}, {<<1, 2>>}}',
        "VARIABLE x\nInit == x = Cardinality({[a |-> 1], [b |-> TRUE]}) + Cardinality({(1 :> 1 @@ 2 :> TRUE), "
        "(1 :> 2 @@ 3 :> 1)}) + Cardinality({{<<1>>}, {<<1, 2>>}})\nNext == UNCHANGED x",
        '',
        Tlc(0, 1, 2, 1, None)),
    'KindCombineFcnKeys': Case(
        '(TRUE :> 1) @@ (1 :> 2) is an error (TLC\'s CombineFcn compares the keys), not (TRUE :> 1)',
        "VARIABLE x\nInit == x = (TRUE :> 1) @@ (1 :> 2)\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of integer 1 with non-integer:\nTRUE')),
    'KindCombineFcnArgument': Case(
        '(1 :> 2) @@ 5 is TLC\'s argument error',
        "VARIABLE x\nInit == x = (1 :> 2) @@ 5\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'The second argument of @@ should be a function, but instead it is:\n5')),
    'KindCombineFcnTuple': Case(
        '<<5, 6>> @@ (3 :> 7) is the sequence <<5, 6, 7>>',
        "VARIABLE x\nInit == x = <<5, 6>> @@ (3 :> 7)\nNext == UNCHANGED x\nInv == x = <<5, 6, 7>>",
        'INVARIANT Inv\n',
        Tlc(0, 1, 2, 1, None)),
    'KindTupleEqualsInt': Case(
        '<<1>> = 1: TLC\'s TupleValue words it "the function ... with the value"',
        "VARIABLE x\nInit == x = (<<1>> = 1)\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of the function <<1>> with the value:\n1')),
    'KindSetEqualsInt': Case(
        '{1} = 1: "the set ... with the value"',
        "VARIABLE x\nInit == x = ({1} = 1)\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of the set {1} with the value:\n1')),
    'KindRecordEqualsInt': Case(
        '[a |-> 1] = 1: "record ... with non-record"',
        "VARIABLE x\nInit == x = ([a |-> 1] = 1)\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of record:\n[a |-> 1]\nwith non-record\n1')),
    'KindIntEqualsTuple': Case(
        '1 = <<1>>: the left operand is named first, as TLC',
        "VARIABLE x\nInit == x = (1 = <<1>>)\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to check equality of integer 1 with non-integer:\n<<1>>')),
    'KindRecordSortedAfterTuple': Case(
        '{<<1, FALSE>>, [val |-> 0]}: TLC\'s sort asks the record to compare itself with a tuple, an error',
        "VARIABLE x\nInit == x = Cardinality({<<1, FALSE>>, [val |-> 0]})\nNext == UNCHANGED x",
        '',
        Tlc(75, 0, 0, 0, 'Attempted to compare record:\n[val |-> 0]\nwith non-record\n<<1, FALSE>>')),
    'KindTupleSortedAfterRecord': Case(
        '{[val |-> 0], <<1, FALSE>>}: the other way round the tuple compares sizes first, a set of two',
        "VARIABLE x\nInit == x = Cardinality({[val |-> 0], <<1, FALSE>>})\nNext == UNCHANGED x\nInv == x = 2",
        'INVARIANT Inv\n',
        Tlc(0, 1, 2, 1, None)),
}

# Outside the native core's subset (refused with "not supported by the native engine").
NATIVE_UNSUPPORTED: set[str] = set()


def _spec(tla_dir, name: str) -> str:
    case = CASES[name]
    tla = f"---- MODULE {name} ----\nEXTENDS Integers, FiniteSets, TLC\n{case.body}\n====\n"
    return str(tla_dir(name, tla, "INIT Init\nNEXT Next\n" + case.cfg_extra))


def _check(path: str, engine: str) -> tuple[int, dict]:
    p = run_safestate("check", path, "--json", "--engine", engine)
    assert "Traceback" not in p.stderr, p.stderr
    return p.returncode, json.loads(p.stdout)


def _engines() -> list:
    out = []
    for name in CASES:
        out.append(pytest.param(name, "python", id=f"{name}-python"))
        if name in NATIVE_UNSUPPORTED:
            continue
        out.append(pytest.param(name, "native", id=f"{name}-native"))
    return out


@pytest.mark.parametrize(("name", "engine"), _engines())
def test_values_of_different_kinds_give_tlc_figures(tla_dir, name: str, engine: str) -> None:
    want = CASES[name].tlc
    code, got = _check(_spec(tla_dir, name), engine)
    assert (code, got["distinct_states"], got["states_generated"], got["depth"]) == (
        want.exit_code, want.distinct, want.generated, want.depth), (CASES[name].what, got)


@pytest.mark.parametrize("name", [n for n, c in CASES.items() if c.tlc.message])
def test_incomparable_kinds_are_tlc_error_message(tla_dir, name: str) -> None:
    code, got = _check(_spec(tla_dir, name), "python")
    assert code == 75
    assert got["error"]["message"].startswith(CASES[name].tlc.message), got["error"]


@pytest.mark.parametrize("name", [n for n, c in CASES.items() if c.tlc.message and n not in NATIVE_UNSUPPORTED])
def test_native_engine_reports_incomparable_kinds_as_python_engine(tla_dir, name: str) -> None:
    """The native core stops where TLC compares values of incomparable kinds (in a set
    it builds, an equality at any depth, a membership, a union, a function
    application): the report is the Python engine's, TLC's message and location."""
    path = _spec(tla_dir, name)
    reports = []
    for engine in ("python", "native"):
        code, got = _check(path, engine)
        got.pop("seconds", None)
        reports.append((code, got))
    assert reports[1] == reports[0]
    assert reports[1][1]["error"]["message"].startswith(CASES[name].tlc.message)


# Kinds that differ below the top level, where the native core compares values as TLC
# (a binary search, an intersection, a function set's domain) and so must not answer
# by id: whatever the Python engine reports, the native engine reports the same (the
# invariant reads the variable, so that the core, not the constant folder, evaluates it).
DEEP_KINDS = {
    'KindDeepMember': "<<TRUE>> \\in {<<1>>}",
    'KindDeepSetMember': "{1} \\in {{TRUE}}",
    'KindDeepIntersect': "{<<1>>} \\cap {<<TRUE>>} = {}",
    'KindDeepUnion': "{<<1>>} \\cup {<<TRUE>>} = {}",
    'KindFnSetDomain': "<<5>> \\in [BOOLEAN -> Nat]",
    'KindRecordInFnSet': "[a |-> 5] \\in [{1} -> Nat]",
}


@pytest.mark.parametrize("name", sorted(DEEP_KINDS))
def test_native_engine_agrees_with_python_engine_on_nested_kinds(tla_dir, name: str) -> None:
    tla = (f"---- MODULE {name} ----\nEXTENDS Naturals, Sequences, FiniteSets, TLC\nVARIABLE v\n"
           f"Init == v = 1\nNext == v' = v\nInv == IF v = 1 THEN {DEEP_KINDS[name]} ELSE TRUE\n====\n")
    path = str(tla_dir(name, tla, "INIT Init\nNEXT Next\nINVARIANT Inv\n"))
    reports = []
    for engine in ("python", "native"):
        code, got = _check(path, engine)
        got.pop("seconds", None)
        reports.append((code, got))
    assert reports[1] == reports[0]


def test_native_engine_refuses_what_it_cannot_check(tla_dir) -> None:
    # An integer beyond the core's 31 bits (TLC's are 32): refused, never wrapped.
    tla = ("---- MODULE KindWide ----\nEXTENDS Integers\nVARIABLE v\nInit == v = 1073741824\nNext == v' = v\n"
           "====\n")
    p = run_safestate("check", str(tla_dir("KindWide", tla, "INIT Init\nNEXT Next\n")), "--engine", "native")
    assert p.returncode == 151 and "not supported by the native engine" in p.stderr
    assert "KindWide.tla:4:" in p.stderr


def test_model_values_compare_unequal_without_error(tla_dir) -> None:
    """TLC: a model value differs from every other value, no error (untyped)."""
    tla = ("---- MODULE KindModelValue ----\nCONSTANT m\nVARIABLE v\nInit == v = 1\nNext == v' = v\n"
           "Inv == m \\notin {1, 2} /\\ m # TRUE /\\ m # <<1>>\n====\n")
    path = tla_dir("KindModelValue", tla, "INIT Init\nNEXT Next\nINVARIANT Inv\nCONSTANT m = m\n")
    code, got = _check(str(path), "python")
    assert (code, got["distinct_states"], got["states_generated"]) == (0, 1, 2)


def test_exact_key_and_same_kinds_tell_true_from_one() -> None:
    from safestate.tla.values import FnValue, exact_key, same_kinds

    # Python's own equality merges these; same_kinds and exact_key must not.
    merged = [((1,), (True,)), (frozenset({0}), frozenset({False})), (((1, 2),), ((True, 2),)),
              (frozenset({(0, 1)}), frozenset({(False, 1)})), (FnValue({"a": 0}), FnValue({"a": False})),
              (FnValue({0: 5, 1: 5}), FnValue({False: 5, True: 5})), (FnValue({"a": 1, "b": True}), FnValue({"b": 1, "a": True})),
              (FnValue({"a": (1,)}), FnValue({"a": (True,)})), (frozenset({FnValue({"v": 0})}), frozenset({FnValue({"v": False})}))]
    for a, b in merged:
        assert a == b
        assert not same_kinds(a, b)
        assert exact_key(a) != exact_key(b)
        assert same_kinds(a, a) and exact_key(a) == exact_key(a)
    same = FnValue({"a": 1, "b": True}), FnValue({"b": True, "a": 1})
    assert same_kinds(*same) and exact_key(same[0]) == exact_key(same[1])


def test_parallel_search_tells_true_from_one(tla_dir) -> None:
    """--workers 2: a worker meeting a state equal to a stored one to Python only flags
    the level, which one process replays with the exact state table.  TLC 1.8.0:
    801 generated, 200 distinct, depth 51."""
    tla = ("---- MODULE KindParallel ----\nEXTENDS Naturals\nVARIABLES n, x\nInit == n = 0 /\\ x = 1\n"
           "Next == n' = (n + 1) % 50 /\\ (x' = TRUE \\/ x' = 1 \\/ x' = 0 \\/ x' = FALSE)\n====\n")
    path = tla_dir("KindParallel", tla, "INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(path), "--json", "--engine", "python", "--workers", "2")
    got = json.loads(p.stdout)
    assert got["parallel"]["workers"] == 2
    assert (p.returncode, got["distinct_states"], got["states_generated"], got["depth"]) == (0, 200, 801, 51)
