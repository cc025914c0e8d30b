"""Native implementations of the TLA+ standard modules.

Naturals, Integers, Sequences, FiniteSets, TLC and Bags are built in (we never
parse their TLA+ text).  Each module maps operator names to `Builtin`s taking
already-evaluated argument values.  Operators that need their arguments
unevaluated (``/\\``, ``\\/``, ``=>``...) are AST nodes, handled by the compiler.
``Reals`` is not supported.  Operators marked ``higher_order`` receive Python
callables for their operator arguments.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import Callable

from .errors import AssertFailure, EvalError, JavaOverrideError, ModuleEvalError, UnsupportedError
from .tlcget import tlc_get, tlc_set
from .values import (
    INT, NAT, FilteredSet, check_same_kind_sets, FnValue, IntervalSet, LazySet, SeqSet, Value, as_set, finite_subseteq, fmt,
    is_finite, iter_set, kind, make_fn, member, set_size, sorted_elems, values_equal, is_set, ModelValue,
    tlc_equals, tlc_fn_items,
)


@dataclass(frozen=True, slots=True)
class Builtin:
    name: str
    arity: int
    fn: Callable[..., Value]
    module: str
    higher_order: bool = False
    # Set for an operator we do not implement: using it is this "unsupported" error.
    refused: str | None = None


COMPARISONS = ("<", "<=", ">", ">=")


def non_integer_error(op: str, v: Value, first: bool) -> EvalError:
    """TLC's error for a non-integer operand of a Naturals operator.  Its Java methods
    for the comparisons check their operands (an evaluation error of the module: exit
    255 in successors, `ModuleEvalError`); those for + - * .. \\div % ^ take integers
    only, so the call itself fails (a Java exception, `JavaOverrideError`)."""
    if op in COMPARISONS:
        return ModuleEvalError(f"The {'first' if first else 'second'} argument of {op} should be an integer, "
                               f"but instead it is:\n{fmt(v)}")
    return JavaOverrideError(f"Attempted to apply the operator {op} to the non-integer {fmt_lazy(v)}")


def fmt_lazy(v: Value) -> str:
    """`v` as TLC prints it, or, for a lazy set whose operands are not sets (`{2} \\X 0`,
    which TLC builds without checking), what it is."""
    try:
        return fmt(v)
    except EvalError:
        return f"lazily built {type(v).__name__}"


def _int(v: Value, op: str, first: bool = True) -> int:
    if type(v) is not int:
        raise non_integer_error(op, v, first)
    return v


def _seq(v: Value, op: str) -> tuple:
    if type(v) is tuple:
        return v
    raise EvalError(f"Attempted to apply {op} to the non-sequence {fmt(v)}")


# ----------------------------------------------------------------- Naturals / Integers


# TLC's integers are Java ints; its Naturals/Integers check +, -, * and ^ for overflow
# (EvalException TLC_MODULE_OVERFLOW, "Overflow when computing a+b"): the result of any
# of them outside this range is that error, never a larger number.
TLC_MIN_INT, TLC_MAX_INT = -(2**31), 2**31 - 1


def overflow(a: int, op: str, b: int) -> ModuleEvalError:
    return ModuleEvalError(f"Overflow when computing {a}{op}{b}")


def _in_range(r: int, a: int, op: str, b: int) -> int:
    if TLC_MIN_INT <= r <= TLC_MAX_INT:
        return r
    raise overflow(a, op, b)


def plus(a: Value, b: Value) -> int:
    x, y = _int(a, "+"), _int(b, "+")
    return _in_range(x + y, x, "+", y)


def minus(a: Value, b: Value) -> int:
    x, y = _int(a, "-"), _int(b, "-")
    return _in_range(x - y, x, "-", y)


def times(a: Value, b: Value) -> int:
    x, y = _int(a, "*"), _int(b, "*")
    return _in_range(x * y, x, "*", y)


def power(a: Value, b: Value) -> int:
    a, b = _int(a, "^"), _int(b, "^")
    if b < 0:
        raise EvalError(f"Attempted to compute {a}^{b}: the exponent must be a natural number")
    if a == 0 and b == 0:
        raise EvalError("0^0 is undefined")
    if abs(a) > 1 and b > 32:  # beyond 32 bits whatever a is: no need to compute a huge power
        raise overflow(a, "^", b)
    return _in_range(a ** b, a, "^", b)


def div(a: Value, b: Value) -> int:
    a, b = _int(a, "\\div"), _int(b, "\\div")
    if b == 0:
        raise ModuleEvalError("The second argument of \\div is 0.")
    if a == TLC_MIN_INT and b == -1:  # the one quotient outside 32 bits (Integers.Divide)
        raise ModuleEvalError(f"Overflow when computing {a} \\div {b}")
    return a // b


def mod(a: Value, b: Value) -> int:
    a, b = _int(a, "%"), _int(b, "%")
    if b <= 0:
        raise ModuleEvalError(f"The second argument of % should be a positive number, but instead it is:\n{b}")
    return a % b


def _cmp(op: str, f: Callable[[int, int], bool]) -> Callable[[Value, Value], bool]:
    def compare(a: Value, b: Value) -> bool:
        return f(_int(a, op), _int(b, op, False))
    return compare


def interval(a: Value, b: Value) -> IntervalSet:
    return IntervalSet(_int(a, ".."), _int(b, ".."))


def negate(a: Value) -> int:
    n = _int(a, "-")
    if n == TLC_MIN_INT:  # TLC's Integers.Neg: the message as TLC writes it
        raise ModuleEvalError(f"Overflow when computing -{n}")
    return -n


NATURALS = {
    "+": Builtin("+", 2, plus, "Naturals"), "-": Builtin("-", 2, minus, "Naturals"),
    "*": Builtin("*", 2, times, "Naturals"), "^": Builtin("^", 2, power, "Naturals"),
    "\\div": Builtin("\\div", 2, div, "Naturals"), "%": Builtin("%", 2, mod, "Naturals"),
    "<": Builtin("<", 2, _cmp("<", lambda a, b: a < b), "Naturals"),
    ">": Builtin(">", 2, _cmp(">", lambda a, b: a > b), "Naturals"),
    "<=": Builtin("<=", 2, _cmp("<=", lambda a, b: a <= b), "Naturals"),
    ">=": Builtin(">=", 2, _cmp(">=", lambda a, b: a >= b), "Naturals"),
    "..": Builtin("..", 2, interval, "Naturals"),
    "Nat": Builtin("Nat", 0, lambda: NAT, "Naturals"),
}
INTEGERS = dict(NATURALS)
INTEGERS.update({
    "Int": Builtin("Int", 0, lambda: INT, "Integers"),
    "-.": Builtin("-.", 1, negate, "Integers"),
})


# ----------------------------------------------------------------- Sequences


def seq_set(s: Value) -> SeqSet:
    if not is_set(s):
        raise EvalError(f"Attempted to apply Seq to the non-set {fmt(s)}")
    return SeqSet(s)


def seq_len(s: Value) -> int:
    if type(s) is str:
        return len(s)
    return len(_seq(s, "Len"))


def head(s: Value) -> Value:
    s = _seq(s, "Head")
    if not s:
        raise ModuleEvalError("Attempted to apply Head to the empty sequence.")
    return s[0]


def tail(s: Value) -> tuple:
    s = _seq(s, "Tail")
    if not s:
        raise ModuleEvalError("Attempted to apply Tail to the empty sequence.")
    return s[1:]


def append(s: Value, e: Value) -> tuple:
    return _seq(s, "Append") + (e,)


def concat(a: Value, b: Value) -> Value:
    if type(a) is str and type(b) is str:
        return a + b
    return _seq(a, "\\o") + _seq(b, "\\o")


def subseq(s: Value, m: Value, n: Value) -> Value:
    m, n = _int(m, "SubSeq"), _int(n, "SubSeq")
    if type(s) is str:
        return s[m - 1:n]
    s = _seq(s, "SubSeq")
    if m > n:
        return ()
    if m < 1 or n > len(s):
        raise EvalError(f"The second and third arguments of SubSeq must be in the domain of its first argument:\n"
                        f"{fmt(s)}, but instead they are: {m} and {n}")
    return s[m - 1:n]


def select_seq(s: Value, test: Callable[[Value], Value]) -> tuple:
    out = []
    for x in _seq(s, "SelectSeq"):
        r = test(x)
        if type(r) is not bool:
            raise EvalError(f"The test of SelectSeq returned the non-boolean {fmt(r)}")
        if r:
            out.append(x)
    return tuple(out)


SEQUENCES = {
    "Seq": Builtin("Seq", 1, seq_set, "Sequences"), "Len": Builtin("Len", 1, seq_len, "Sequences"),
    "Head": Builtin("Head", 1, head, "Sequences"), "Tail": Builtin("Tail", 1, tail, "Sequences"),
    "Append": Builtin("Append", 2, append, "Sequences"), "\\o": Builtin("\\o", 2, concat, "Sequences"),
    "SubSeq": Builtin("SubSeq", 3, subseq, "Sequences"),
    "SelectSeq": Builtin("SelectSeq", 2, select_seq, "Sequences", higher_order=True),
}


# ----------------------------------------------------------------- FiniteSets


def is_finite_set(s: Value) -> bool:
    if type(s) is frozenset:
        return True
    if isinstance(s, LazySet):
        return s.finite
    raise EvalError(f"Attempted to apply IsFiniteSet to the non-set {fmt(s)}")


def cardinality(s: Value) -> int:
    if not is_set(s):
        raise EvalError(f"Attempted to compute the cardinality of the non-set {fmt(s)}")
    if not is_finite(s):  # TLC: FiniteSets' own error (exit 255 while computing successors)
        raise ModuleEvalError(f"Attempted to compute cardinality of the value\n{s.describe()}")
    return set_size(s)


FINITE_SETS = {
    "IsFiniteSet": Builtin("IsFiniteSet", 1, is_finite_set, "FiniteSets"),
    "Cardinality": Builtin("Cardinality", 1, cardinality, "FiniteSets"),
}


# ----------------------------------------------------------------- TLC


def print_op(out: Value, val: Value) -> Value:
    print(fmt(out), file=sys.stderr)
    return val


def print_t(out: Value) -> bool:
    print(fmt(out), file=sys.stderr)
    return True


def assert_op(cond: Value, msg: Value) -> bool:
    if cond is not True:
        if cond is False:
            raise AssertFailure(f"The first argument of Assert evaluated to FALSE; the second argument was:\n"
                                f"{fmt(msg)}")
        raise EvalError(f"The first argument of Assert is not a boolean: {fmt(cond)}")
    return True


def single_fn(k: Value, v: Value) -> Value:
    return make_fn({k: v})


def fn_items(f: Value, which: str = "first") -> dict:
    if type(f) is tuple:
        return {i + 1: x for i, x in enumerate(f)}
    if type(f) is FnValue:
        return f.d
    raise ModuleEvalError(f"The {which} argument of @@ should be a function, but instead it is:\n{fmt(f)}")


_PLAIN_KEYS = (int, str)


def merge_fn(f: Value, g: Value) -> Value:
    """TLC's CombineFcn: f's keys, then each key of g that equals none of them, looked
    up with TLC's ``equals`` (an error for keys of incomparable kinds: ``(TRUE :> 1) @@
    (1 :> 2)``, which a Python dict would merge)."""
    d1, d2 = fn_items(f), fn_items(g, "second")
    types = set(map(type, d1)) | set(map(type, d2))
    if len(types) == 1 and types <= set(_PLAIN_KEYS):
        d = dict(d2)
        d.update(d1)
        return make_fn(d)
    keys1 = [k for k, _ in tlc_fn_items(f)]
    d = dict(d1)
    for k2, v2 in tlc_fn_items(g):
        if not any(tlc_equals(k2, k1) for k1 in keys1):
            d[k2] = v2
    return make_fn(d)


def permutations(s: Value) -> frozenset:
    import itertools
    elems = sorted_elems(as_set(s))
    return frozenset(make_fn(dict(zip(elems, p))) for p in itertools.permutations(elems))


def sort_seq(s: Value, less: Callable[[Value, Value], Value]) -> tuple:
    import functools
    seq = list(_seq(s, "SortSeq"))

    def cmp(a: Value, b: Value) -> int:
        if less(a, b) is True:
            return -1
        if less(b, a) is True:
            return 1
        return 0
    return tuple(sorted(seq, key=functools.cmp_to_key(cmp)))


def to_string(v: Value) -> str:
    return fmt(v)


def tlc_eval(v: Value) -> Value:
    return v


TLC = {
    "Print": Builtin("Print", 2, print_op, "TLC"), "PrintT": Builtin("PrintT", 1, print_t, "TLC"),
    "Assert": Builtin("Assert", 2, assert_op, "TLC"), ":>": Builtin(":>", 2, single_fn, "TLC"),
    "@@": Builtin("@@", 2, merge_fn, "TLC"), "Permutations": Builtin("Permutations", 1, permutations, "TLC"),
    "SortSeq": Builtin("SortSeq", 2, sort_seq, "TLC", higher_order=True),
    "ToString": Builtin("ToString", 1, to_string, "TLC"), "TLCEval": Builtin("TLCEval", 1, tlc_eval, "TLC"),
    "TLCGet": Builtin("TLCGet", 1, tlc_get, "TLC"), "TLCSet": Builtin("TLCSet", 2, tlc_set, "TLC"),
}


# ----------------------------------------------------------------- Bags


def _bag(b: Value) -> dict:
    if type(b) is FnValue:
        return b.d
    if type(b) is tuple:
        return {i + 1: x for i, x in enumerate(b)}
    raise EvalError(f"Attempted to use the non-bag {fmt(b)} as a bag")


def set_to_bag(s: Value) -> Value:
    return make_fn({x: 1 for x in iter_set(s)})


def bag_to_set(b: Value) -> frozenset:
    return frozenset(k for k, c in _bag(b).items() if c > 0)


def bag_in(e: Value, b: Value) -> bool:
    return _bag(b).get(e, 0) > 0


def copies_in(e: Value, b: Value) -> int:
    return _bag(b).get(e, 0)


def bag_cup(a: Value, b: Value) -> Value:
    d = dict(_bag(a))
    for k, c in _bag(b).items():
        d[k] = d.get(k, 0) + c
    return make_fn(d)


def bag_minus(a: Value, b: Value) -> Value:
    d = dict(_bag(a))
    for k, c in _bag(b).items():
        if k in d:
            d[k] -= c
    return make_fn({k: c for k, c in d.items() if c > 0})


def is_a_bag(b: Value) -> bool:
    try:
        return all(type(c) is int and c > 0 for c in _bag(b).values())
    except EvalError:
        return False


def bag_cardinality(b: Value) -> int:
    return sum(_bag(b).values())


def sub_bag(a: Value, b: Value) -> bool:
    db = _bag(b)
    return all(db.get(k, 0) >= c for k, c in _bag(a).items())


def empty_bag() -> Value:
    return ()


def bag_union(s: Value) -> Value:
    """BagUnion(S): the bag sum of the bags in the set S."""
    d: dict = {}
    for b in iter_set(s):
        for k, c in _bag(b).items():
            d[k] = d.get(k, 0) + c
    return make_fn(d)


def sub_bags(b: Value) -> frozenset:
    """SubBag(B): every bag SB with SB[e] <= B[e] (EmptyBag included)."""
    import itertools
    items = [(k, c) for k, c in _bag(b).items() if c > 0]
    out = []
    for counts in itertools.product(*[range(c + 1) for _, c in items]):
        out.append(make_fn({k: n for (k, _), n in zip(items, counts) if n > 0}))
    return frozenset(out)


def bag_of_all(f: Callable[[Value], Value], b: Value) -> Value:
    """BagOfAll(F, B): the bag of F(e) for the elements e of B, with their copies."""
    d: dict = {}
    for k, c in _bag(b).items():
        if c > 0:
            y = f(k)
            d[y] = d.get(y, 0) + c
    return make_fn(d)


BAGS = {
    "SetToBag": Builtin("SetToBag", 1, set_to_bag, "Bags"), "BagToSet": Builtin("BagToSet", 1, bag_to_set, "Bags"),
    "BagIn": Builtin("BagIn", 2, bag_in, "Bags"), "CopiesIn": Builtin("CopiesIn", 2, copies_in, "Bags"),
    "(+)": Builtin("(+)", 2, bag_cup, "Bags"), "(-)": Builtin("(-)", 2, bag_minus, "Bags"),
    "IsABag": Builtin("IsABag", 1, is_a_bag, "Bags"), "BagCardinality": Builtin("BagCardinality", 1, bag_cardinality, "Bags"),
    "\\sqsubseteq": Builtin("\\sqsubseteq", 2, sub_bag, "Bags"), "EmptyBag": Builtin("EmptyBag", 0, empty_bag, "Bags"),
    "BagUnion": Builtin("BagUnion", 1, bag_union, "Bags"), "SubBag": Builtin("SubBag", 1, sub_bags, "Bags"),
    "BagOfAll": Builtin("BagOfAll", 2, bag_of_all, "Bags", higher_order=True),
}

# TLCExt: the operators whose value TLC defines deterministically.  The others are
# Java overrides that read TLC's own state (Trace, CounterExample, TLCFP...), change
# its search (TLCDefer, PickSuccessor) or catch its errors (AssertError): using one is
# an "unsupported" error, never a guess.


def assert_eq(a: Value, b: Value) -> bool:
    """TLCExt's definition: a = b, printing both when they differ."""
    if values_equal(a, b):
        return True
    for v in ("Assertion failed", a, b):
        print_t(v)
    return False


def _refused(name: str, arity: int) -> Builtin:
    def refuse(*_: Value) -> Value:
        raise UnsupportedError(message)
    message = (f"TLCExt!{name} is not supported: TLC computes it from its own search state, which "
               f"safestate check does not reproduce")
    return Builtin(name, arity, refuse, "TLCExt", refused=message)


TLC_EXT = {
    "AssertEq": Builtin("AssertEq", 2, assert_eq, "TLCExt"),
    "TLCNoOp": Builtin("TLCNoOp", 1, lambda v: v, "TLCExt"),
    "TLCCache": Builtin("TLCCache", 2, lambda e, _closure: e, "TLCExt"),
    "TLCModelValue": Builtin("TLCModelValue", 1, lambda s: ModelValue(s) if type(s) is str else _not_string(s),
                             "TLCExt"),
    **{n: _refused(n, a) for n, a in (("AssertError", 2), ("TLCGetOrDefault", 2), ("TLCGetAndSet", 4),
                                       ("Trace", 0), ("CounterExample", 0), ("ToTrace", 1), ("TLCDefer", 1),
                                       ("PickSuccessor", 1), ("TLCFP", 1), ("TLCEvalDefinition", 1))},
}


def _not_string(v: Value) -> Value:
    raise EvalError(f"TLCModelValue expects a string, not {fmt(v)}")


STANDARD_MODULES: dict[str, dict[str, Builtin]] = {
    "Naturals": NATURALS, "Integers": INTEGERS, "Sequences": SEQUENCES, "FiniteSets": FINITE_SETS,
    "TLC": TLC, "Bags": BAGS, "TLCExt": TLC_EXT,
}
# Modules TLC ships that we do not implement: naming them is an "unsupported" error.
UNSUPPORTED_MODULES = {"Reals", "RealTime", "Json", "Randomization", "IOUtils", "CSV"}


# ----------------------------------------------------------------- core set operators


def _sets(a: Value, b: Value, op: str) -> tuple[frozenset, frozenset]:
    if not is_set(a):
        raise EvalError(f"Attempted to apply {op} to the non-set {fmt(a)}")
    if not is_set(b):
        raise EvalError(f"Attempted to apply {op} to the non-set {fmt(b)}")
    return as_set(a), as_set(b)


def _infinite(v: Value) -> bool:
    return isinstance(v, LazySet) and not v.finite


def _empty_enumerated(v: Value) -> bool:
    """An empty set that TLC holds as a SetEnumValue or an IntervalValue (its
    `Reducible` sets)."""
    return (type(v) is frozenset and not v) or (type(v) is IntervalSet and v.size() == 0)


def cup(a: Value, b: Value) -> Value:
    # TLC returns the other operand itself for `{} \cup S` (and for `S \cup {}` when S is
    # not a SetEnumValue/IntervalValue), so `{} \cup 0..2` stays `0..2` in a trace.
    if is_set(b) and _empty_enumerated(a):
        return b
    if is_set(a) and _empty_enumerated(b) and type(a) not in (frozenset, IntervalSet):
        return a
    if _infinite(a) or _infinite(b):
        _need_sets(a, b, "\\cup")
        return FilteredSet(lambda v: member(v, a) or member(v, b), f"{fmt(a)} \\cup {fmt(b)}")
    x, y = _sets(a, b, "\\cup")
    check_same_kind_sets(x, y, "\\cup")
    return x | y


def _need_sets(a: Value, b: Value, op: str) -> None:
    for v in (a, b):
        if not is_set(v):
            raise EvalError(f"Attempted to apply {op} to the non-set {fmt(v)}")


def cap(a: Value, b: Value) -> Value:
    if _infinite(a) and _infinite(b):
        return FilteredSet(lambda v: member(v, a) and member(v, b), f"{fmt(a)} \\cap {fmt(b)}")
    if _infinite(a):
        a, b = b, a
    if type(a) is frozenset and isinstance(b, LazySet):
        return frozenset(x for x in a if b.contains(x))
    x, y = _sets(a, b, "\\cap")
    check_same_kind_sets(x, y, "\\cap")
    return x & y


def setminus(a: Value, b: Value) -> Value:
    if _infinite(a):
        _need_sets(a, b, "\\")
        return FilteredSet(lambda v: member(v, a) and not member(v, b), f"{fmt(a)} \\ {fmt(b)}")
    if type(a) is frozenset and isinstance(b, LazySet):
        return frozenset(x for x in a if not b.contains(x))
    x, y = _sets(a, b, "\\")
    check_same_kind_sets(x, y, "\\")
    return x - y


def subseteq(a: Value, b: Value) -> bool:
    if not is_set(a) or not is_set(b):
        raise EvalError(f"Attempted to apply \\subseteq to a non-set: {fmt(a)}, {fmt(b)}")
    if type(b) is frozenset:
        return finite_subseteq(as_set(a), b)
    return all(member(x, b) for x in iter_set(a))


def union(s: Value) -> Value:
    parts = list(s) if type(s) is frozenset else list(iter_set(s))  # order is irrelevant here
    for x in parts:
        if not is_set(x):
            raise EvalError(f"Attempted to apply UNION to a set containing the non-set {fmt(x)}")
    if any(_infinite(x) for x in parts):
        # UNION {[D -> Int]}: only membership can be tested, as TLC's UnionValue.
        return FilteredSet(lambda v: any(member(v, x) for x in parts), "UNION {" + ", ".join(
            x.describe() if isinstance(x, LazySet) else fmt(x) for x in parts) + "}",
            "Attempted to enumerate UNION(s), but some element of s is nonenumerable.")
    out: set = set()
    for x in parts:
        out |= as_set(x)
    return frozenset(out)


def domain(f: Value) -> Value:
    if type(f) is tuple:
        return IntervalSet(1, len(f))
    if type(f) is FnValue:
        return frozenset(f.d)
    if hasattr(f, "domain"):
        return f.domain
    if type(f) is str:
        return IntervalSet(1, len(f))
    raise EvalError(f"Attempted to apply the operator DOMAIN to a non-function:\n{fmt(f)}")


__all__ = ["Builtin", "STANDARD_MODULES", "UNSUPPORTED_MODULES", "cup", "cap", "setminus", "subseteq",
           "union", "domain", "values_equal", "kind", "ModelValue"]
