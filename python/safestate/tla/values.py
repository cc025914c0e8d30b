"""TLA+ values as canonical, hashable Python objects.

Representation (chosen so that Python equality *is* TLA+ equality and states can be
hashed as plain tuples):

* BOOLEAN -> ``bool``; integers -> ``int``; strings -> ``str``;
* model values -> `ModelValue` (interned by name);
* functions whose domain is ``1..n`` (tuples, sequences, and e.g. ``[i \\in 1..2 |-> i]``)
  -> ``tuple``; the empty function is ``()``;
* every other function, records included (records are functions over strings)
  -> `FnValue` wrapping a dict;
* finite sets -> ``frozenset``; intervals and the structured sets ``SUBSET S``,
  ``[S -> T]``, ``[a : S]``, ``S \\X T``, ``Seq(S)``, ``Nat``, ``Int``, ``STRING`` ->
  `LazySet` subclasses that test membership without enumerating, and materialise
  to a frozenset only when a finite set is really needed.

Python's ``True == 1`` and ``hash(True) == hash(1)``, so TLA+ ``TRUE``/``1`` and
``FALSE``/``0`` are *equal* Python values, at any depth (``(1,) == (True,)``).  Where that
would make two different TLA+ values one, the kind is checked explicitly:

* `same_kinds(a, b)` tells, for Python-equal values, whether they are the same TLA+
  value (cheap, conservative); `exact_key(v)` is a key whose Python equality is TLA+
  equality (a full walk, for the rare cases `same_kinds` cannot decide).  The state
  table (`checker/explore.py`) and the memo tables use them;
* comparisons TLC refuses (``1 = TRUE``, ``1 \\in BOOLEAN``, ``{1, TRUE}``, ``<<1>> =
  <<TRUE>>``) raise TLC's error (`values_equal`, `member`, `check_set_kinds`).
"""

from __future__ import annotations

import itertools
from itertools import chain, compress
from operator import is_, is_not
from typing import Any, Callable, Iterable, Iterator

from .enum_watch import ENUM_WATCH
from .errors import EvalError

Value = Any


class ModelValue:
    """A TLC model value (declared in the .cfg as ``a = a`` or ``S = {a, b}``)."""

    # Hashed by name, not by identity: processes that each load the model (a search
    # sharded over machines) must agree on which shard owns a state.
    __slots__ = ("name", "rank", "_hash")
    name: str
    rank: int
    _hash: int
    _interned: dict[str, "ModelValue"] = {}

    def __new__(cls, name: str) -> "ModelValue":
        mv = cls._interned.get(name)
        if mv is None:
            mv = object.__new__(cls)
            mv.name = name
            mv.rank = len(cls._interned)
            mv._hash = hash(("ModelValue", name))
            cls._interned[name] = mv
        return mv

    def __hash__(self) -> int:
        return self._hash

    def __reduce__(self) -> tuple:
        return (ModelValue, (self.name,))

    def __repr__(self) -> str:
        return self.name


class FnValue:
    """A function that is not a tuple: a record or a function with a non-``1..n`` domain."""

    __slots__ = ("d", "_hash")

    def __init__(self, d: dict) -> None:
        self.d = d
        self._hash = -1

    def __eq__(self, other: object) -> bool:
        return type(other) is FnValue and (self is other or self.d == other.d)  # type: ignore[union-attr]

    def __ne__(self, other: object) -> bool:
        return not self.__eq__(other)

    def __hash__(self) -> int:
        h = self._hash
        if h == -1:
            h = self._hash = hash(frozenset(self.d.items()))
        return h

    def __reduce__(self) -> tuple:
        return (FnValue, (self.d,))

    def __repr__(self) -> str:
        return fmt(self)


def make_fn(d: dict) -> Value:
    """Canonical function value for the mapping `d` (a tuple when the domain is 1..n)."""
    n = len(d)
    if n == 0:
        return ()
    if 1 in d and n in d:
        keys_ok = True
        for k in d:
            if type(k) is not int or k < 1 or k > n:
                keys_ok = False
                break
        if keys_ok:
            return tuple(d[i] for i in range(1, n + 1))
    return FnValue(d)


# ----------------------------------------------------------------- lazy sets


class LazySet:
    """A set given by a rule; membership without enumeration, enumeration in TLC's order."""

    __slots__ = ("_mat",)
    finite = True

    def contains(self, v: Value) -> bool:
        raise NotImplementedError

    def iterate(self) -> Iterator[Value]:
        raise NotImplementedError

    def describe(self) -> str:
        raise NotImplementedError

    def materialize(self) -> frozenset:
        m = getattr(self, "_mat", None)
        if m is None:
            if not self.finite:
                raise EvalError(f"Attempted to enumerate the infinite set {self.describe()}")
            m = frozenset(ENUM_WATCH.watched(self.iterate(), self.describe))
            self._mat = m
        return m

    def size(self) -> int:
        return len(self.materialize())

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        if isinstance(other, (frozenset, LazySet)):
            if not self.finite or (isinstance(other, LazySet) and not other.finite):
                return type(self) is type(other) and self.describe() == other.describe()
            return self.materialize() == as_set(other)
        return False

    def __hash__(self) -> int:
        if not self.finite:
            return hash(self.describe())
        return hash(self.materialize())

    def __reduce__(self) -> tuple:
        return (frozenset, (tuple(self.materialize()),)) if self.finite else (type(self), ())

    def __repr__(self) -> str:
        return self.describe()


class IntervalSet(LazySet):
    __slots__ = ("lo", "hi")

    def __init__(self, lo: int, hi: int) -> None:
        self.lo, self.hi = lo, hi

    def contains(self, v: Value) -> bool:
        return (self.lo <= v <= self.hi) if type(v) is int else interval_member(v, self.lo, self.hi)

    def iterate(self) -> Iterator[Value]:
        return iter(range(self.lo, self.hi + 1))

    def size(self) -> int:
        return max(0, self.hi - self.lo + 1)

    def describe(self) -> str:
        return f"{self.lo}..{self.hi}" if self.lo <= self.hi else "{}"

    def __reduce__(self) -> tuple:
        return (IntervalSet, (self.lo, self.hi))


def interval_member(v: Value, lo: int, hi: int) -> bool:
    """``v \\in lo..hi`` as TLC's IntervalValue.member: a value that is neither an integer
    nor a model value is an error, unless the interval is empty."""
    if type(v) is int:
        return lo <= v <= hi
    if type(v) is ModelValue or lo > hi:
        return False
    raise EvalError(f"Attempted to check if the value:\n{fmt(v)}\nis in the integer interval {lo}..{hi}")


def _not_of_kind(v: Value, name: str) -> bool:
    """Membership of a value of another kind in Nat, Int or STRING: FALSE for a model
    value, TLC's error for anything else."""
    if type(v) is ModelValue:
        return False
    raise EvalError(f"Attempted to check if the value:\n{fmt(v)}\nis an element of {name}.")


class _InfiniteSet(LazySet):
    __slots__ = ()
    finite = False
    name = ""

    def describe(self) -> str:
        return self.name

    def iterate(self) -> Iterator[Value]:
        raise EvalError(f"Attempted to enumerate the infinite set {self.name}")

    def __reduce__(self) -> tuple:
        return (type(self), ())


class NatSet(_InfiniteSet):
    __slots__ = ()
    name = "Nat"

    def contains(self, v: Value) -> bool:
        if type(v) is int:
            return v >= 0
        return _not_of_kind(v, "Nat")


class IntSet(_InfiniteSet):
    __slots__ = ()
    name = "Int"

    def contains(self, v: Value) -> bool:
        return type(v) is int or _not_of_kind(v, "Int")


class StringSet(_InfiniteSet):
    __slots__ = ()
    name = "STRING"

    def contains(self, v: Value) -> bool:
        return type(v) is str or _not_of_kind(v, "STRING")


class SeqSet(LazySet):
    """``Seq(S)``: infinite unless S is empty."""

    __slots__ = ("base",)
    finite = False

    def __init__(self, base: Value) -> None:
        self.base = base

    def contains(self, v: Value) -> bool:
        return type(v) is tuple and all(member(x, self.base) for x in v)

    def iterate(self) -> Iterator[Value]:
        raise EvalError(f"Attempted to enumerate the infinite set Seq({fmt(self.base)})")

    def describe(self) -> str:
        return f"Seq({fmt(self.base)})"

    def __reduce__(self) -> tuple:
        return (SeqSet, (self.base,))


class PowerSet(LazySet):
    """``SUBSET S``; enumerated by increasing size like TLC's normalised order."""

    __slots__ = ("base", "finite")

    def __init__(self, base: Value) -> None:
        self.base = base
        self.finite = is_finite(base)

    def contains(self, v: Value) -> bool:
        if not isinstance(v, (frozenset, LazySet)):
            return False
        return all(member(x, self.base) for x in iter_set(v))

    def iterate(self) -> Iterator[Value]:
        elems = sorted_elems(self.base)
        for k in range(len(elems) + 1):
            for combo in itertools.combinations(elems, k):
                yield frozenset(combo)

    def size(self) -> int:
        return 2 ** set_size(self.base)

    def describe(self) -> str:
        return f"SUBSET {fmt(self.base)}"

    def __reduce__(self) -> tuple:
        return (PowerSet, (self.base,))


class FnSetValue(LazySet):
    """``[D -> R]``."""

    __slots__ = ("dom", "rng", "finite")

    def __init__(self, dom: Value, rng: Value) -> None:
        self.dom, self.rng = dom, rng
        self.finite = is_finite(dom) and (is_finite(rng) or set_size(dom) == 0)

    def contains(self, v: Value) -> bool:
        if type(v) is tuple:
            vals: Iterable = v
            if not set_equal_keys(self.dom, len(v), None):
                return False
        elif type(v) is FnValue:
            if not set_equal_keys(self.dom, len(v.d), v.d):
                return False
            vals = v.d.values()
        else:
            return False
        rng = self.rng
        return all(member(x, rng) for x in vals)

    def iterate(self) -> Iterator[Value]:
        dom = sorted_elems(self.dom)
        rng = sorted_elems(self.rng)
        for combo in itertools.product(rng, repeat=len(dom)):
            yield make_fn(dict(zip(dom, combo)))

    def size(self) -> int:
        return set_size(self.rng) ** set_size(self.dom)

    def describe(self) -> str:
        return f"[{fmt(self.dom)} -> {fmt(self.rng)}]"

    def __reduce__(self) -> tuple:
        return (FnSetValue, (self.dom, self.rng))


class RecSetValue(LazySet):
    """``[a : S, b : T]``."""

    __slots__ = ("fields", "finite")

    def __init__(self, fields: tuple[tuple[str, Value], ...]) -> None:
        self.fields = fields
        self.finite = all(is_finite(s) for _, s in fields)

    def contains(self, v: Value) -> bool:
        if type(v) is not FnValue or len(v.d) != len(self.fields):
            return False
        d = v.d
        for name, s in self.fields:
            if name not in d or not member(d[name], s):
                return False
        return True

    def iterate(self) -> Iterator[Value]:
        # TLC's order (its order of the records): the fields in the order of their names
        # (string_rank, not as written), the last one turning fastest.
        fields = sorted(self.fields, key=lambda f: string_rank(f[0]))
        names = [n for n, _ in fields]
        for combo in itertools.product(*(sorted_elems(s) for _, s in fields)):
            yield FnValue(dict(zip(names, combo)))

    def size(self) -> int:
        n = 1
        for _, s in self.fields:
            n *= set_size(s)
        return n

    def describe(self) -> str:
        return "[" + ", ".join(f"{n} : {fmt(s)}" for n, s in self.fields) + "]"

    def __reduce__(self) -> tuple:
        return (RecSetValue, (self.fields,))


class ProductSet(LazySet):
    """``S1 \\X S2 \\X ...``.  As TLC's SetOfTuplesValue, a factor that is not a set
    is an error only when the product is used as a set (``({2} \\X 0)..2`` fails in
    ``..``, as in TLC)."""

    __slots__ = ("factors", "finite")

    def __init__(self, factors: tuple[Value, ...]) -> None:
        self.factors = factors
        self.finite = all(is_finite(s) for s in factors if is_set(s))

    def _sets(self) -> tuple[Value, ...]:
        for s in self.factors:
            if not is_set(s):
                raise EvalError(f"Attempted to apply \\X to the non-set {fmt(s)}")
        return self.factors

    def contains(self, v: Value) -> bool:
        factors = self._sets()
        if type(v) is not tuple or len(v) != len(factors):
            return False
        return all(member(x, s) for x, s in zip(v, factors))

    def iterate(self) -> Iterator[Value]:
        return iter(itertools.product(*(sorted_elems(s) for s in self._sets())))

    def size(self) -> int:
        n = 1
        for s in self._sets():
            n *= set_size(s)
        return n

    def describe(self) -> str:
        return " \\X ".join(fmt(s) for s in self.factors)

    def __reduce__(self) -> tuple:
        return (ProductSet, (self.factors,))


class FilteredSet(LazySet):
    """An infinite set combined with another set: ``Nat \\ {0}``, ``Int \\cup {..}``..."""

    __slots__ = ("test", "text", "finite", "java_error")

    def __init__(self, test: Any, text: str, java_error: str | None = None) -> None:
        self.test, self.text, self.finite = test, text, False
        # TLC's message where its Java code throws instead of reporting (UNION {Nat}
        # held in a state: "TLC threw an unexpected exception", exit 255).
        self.java_error = java_error

    def contains(self, v: Value) -> bool:
        return self.test(v)

    def iterate(self) -> Iterator[Value]:
        raise EvalError(f"Attempted to enumerate the infinite set {self.text}")

    def describe(self) -> str:
        return self.text

    def __reduce__(self) -> tuple:
        raise TypeError("infinite sets cannot be stored in states")


NAT = NatSet()
INT = IntSet()
STRING = StringSet()
BOOLEAN = frozenset((False, True))


# ----------------------------------------------------------------- set helpers


def is_set(v: Value) -> bool:
    return type(v) is frozenset or isinstance(v, LazySet)


def is_finite(s: Value) -> bool:
    if type(s) is frozenset:
        return True
    if isinstance(s, LazySet):
        return s.finite
    raise EvalError(f"Attempted to use a non-set value as a set: {fmt(s)}")


def set_size(s: Value) -> int:
    if type(s) is frozenset:
        return len(s)
    if isinstance(s, LazySet):
        if not s.finite:
            raise EvalError(f"Attempted to compute the cardinality of the infinite set {s.describe()}")
        return s.size()
    raise EvalError(f"Attempted to compute the cardinality of a non-set: {fmt(s)}")


def as_set(v: Value) -> frozenset:
    """The finite set `v` as a frozenset (error for non-sets and infinite sets)."""
    if type(v) is frozenset:
        return v
    if isinstance(v, LazySet):
        return v.materialize()
    raise EvalError(f"Attempted to use a non-set value as a set: {fmt(v)}")


def member(v: Value, s: Value) -> bool:
    if type(s) is frozenset:
        if type(v) in _CONTAINERS and s:
            return _container_member(v, s)
        r = v in s
        if s and not _same_kind_as_elements(v, s):
            member_kind_check(v, s)
        return r
    if isinstance(s, LazySet):
        return s.contains(v)
    raise EvalError(f"Attempted to check if the value:\n{fmt(v)}\nis an element of the non-set {fmt(s)}")


def finite_subseteq(x: frozenset, b: frozenset) -> bool:
    """``x \\subseteq b`` for finite sets: Python's `<=` where every element on both
    sides has the same kind signature (the signatures are cached per set), otherwise
    element by element through `member` and its checks of TLC's comparisons."""
    sigs = _element_sigs(b)
    if not x or (len(sigs) == 1 and sigs[0] is not None and _element_sigs(x) == sigs):
        return x <= b
    return all(member(v, b) for v in x)


def _container_member(v: Value, s: frozenset) -> bool:
    """A tuple, function, record or set looked up in a finite set.  Python's `in` is
    TLA+'s answer only where no position can hold TRUE on one side and 1 on the other:
    when `v` and every element have the same kind signature.  Otherwise TLC's binary
    search decides, with its error at a pair of incomparable kinds."""
    sig = kind_sig(v)
    if sig is not None and _element_sigs(s) == (sig,):
        return v in s
    tlc_search(v, s)  # TLC's error, if its search compares incomparable kinds
    return exact_key(v) in _exact_keys(s)


def _per_set(cache: dict[int, tuple[frozenset, Any]], s: frozenset, compute: Callable[[frozenset], Any]) -> Any:
    """`compute(s)`, cached per set object (keyed by identity: Python's equality would
    take {0} for {FALSE})."""
    hit = cache.get(id(s))
    if hit is not None and hit[0] is s:
        return hit[1]
    if len(cache) > 20000:
        cache.clear()
    out = compute(s)
    cache[id(s)] = (s, out)
    return out


_EXACT_CACHE: dict[int, tuple[frozenset, Any]] = {}
_SIG_CACHE: dict[int, tuple[frozenset, Any]] = {}


def _exact_keys(s: frozenset) -> frozenset:
    """The `exact_key`s of the elements of `s`."""
    return _per_set(_EXACT_CACHE, s, lambda x: frozenset(map(exact_key, x)))


def _element_sigs(s: frozenset) -> tuple:
    """The distinct kind signatures of the elements of `s`; (None,) if one is unknown."""
    def sigs(x: frozenset) -> tuple:
        out = tuple({kind_sig(e) for e in x})
        return (None,) if None in out else out
    return _per_set(_SIG_CACHE, s, sigs)


_SIG_SCALARS: dict[type, str] = {bool: "b", int: "i", str: "s"}


def kind_sig(v: Value) -> Any:
    """The kinds at every position of `v` (None where that cannot be told cheaply: model
    values, non-record functions, sets of mixed signatures, lazy sets).  Two values with
    the same signature are compared by TLC without meeting incomparable kinds, so
    Python's equality is TLA+'s between them."""
    t = type(v)
    r = _SIG_SCALARS.get(t)
    if r is not None:
        return r
    if t is tuple:
        parts = tuple(map(kind_sig, v))
        return None if None in parts else ("t", parts)
    if t is FnValue:
        if not all(type(k) is str for k in v.d):
            return None
        fields = tuple(sorted((k, kind_sig(x)) for k, x in v.d.items()))
        return None if any(x is None for _, x in fields) else ("r", fields)
    if t is frozenset:
        if not v:
            return ("s", "empty")
        sigs = _element_sigs(v)
        return ("s", sigs[0]) if len(sigs) == 1 and sigs[0] is not None else None
    return None


def _same_kind_as_elements(v: Value, s: frozenset) -> bool:
    """True when looking `v` up in the non-empty set `s` cannot compare incomparable
    kinds: `v` has the type of (an element of) `s` and, for a container, Python's
    answer is TLA+'s.  False means "check" (`member_kind_check`)."""
    tv = type(v)
    te = type(next(iter(s)))
    if tv is te:
        return True
    # A tuple looked up among functions, a set among lazy sets: the same kind.
    return tv in _CONTAINERS and te in _CONTAINERS and (tv is frozenset) is (te is frozenset)


def set_equal_keys(dom: Value, n: int, d: dict | None) -> bool:
    """Is `dom` exactly the domain of a function with dict `d` (or 1..n when d is None)?"""
    if set_size(dom) != n:
        return False
    if d is None:
        return all(member(i, dom) for i in range(1, n + 1))
    return all(member(k, dom) for k in d)


# ----------------------------------------------------------------- TLC order

# TLC orders strings (and model values) by when their name was first interned, which
# is roughly the order of first appearance in the .cfg and the modules.  We keep the
# same order so that CHOOSE and enumeration agree with TLC.
_STRING_RANK: dict[str, int] = {}


def reset_token_order() -> None:
    """Forget the order of an earlier model (each check is a TLC run of its own)."""
    _STRING_RANK.clear()
    _SORTED_CACHE.clear()


def register_token_order(tokens: Iterable[str]) -> None:
    for t in tokens:
        if t not in _STRING_RANK:
            _STRING_RANK[t] = len(_STRING_RANK)


def string_rank(s: str) -> int:
    r = _STRING_RANK.get(s)
    if r is None:
        r = _STRING_RANK[s] = len(_STRING_RANK)
    return r


def tlc_key(v: Value) -> tuple:
    """Sort key reproducing TLC's normalised order within values of one kind."""
    t = type(v)
    if t is int:
        return (1, v)
    if t is bool:
        return (0, v)
    if t is str:
        return (2, string_rank(v))
    if t is ModelValue:
        return (3, string_rank(v.name))
    if t is tuple:
        return (4, len(v), (), tuple(tlc_key(x) for x in v))
    if t is FnValue:
        keys = sorted(v.d, key=tlc_key)
        return (4, len(keys), tuple(tlc_key(k) for k in keys), tuple(tlc_key(v.d[k]) for k in keys))
    if t is frozenset or isinstance(v, LazySet):
        elems = sorted_elems(v)
        return (5, len(elems), tuple(tlc_key(x) for x in elems))
    return (9, repr(v))


_SORTED_CACHE: dict[frozenset, tuple[frozenset, tuple]] = {}


def sorted_elems(s: Value) -> tuple:
    """The elements of a finite set in TLC's enumeration order."""
    if type(s) is frozenset:
        hit = _SORTED_CACHE.get(s)
        # {0, 1} == {FALSE, TRUE} in Python: a hit must be for the same TLA+ set.
        if hit is not None and (hit[0] is s or same_kinds(hit[0], s)):
            return hit[1]
        if len(_SORTED_CACHE) > 20000:
            _SORTED_CACHE.clear()
        if all(type(x) is int for x in s):
            r = tuple(sorted(s))
        else:
            r = tuple(sorted(s, key=tlc_key))
        _SORTED_CACHE[s] = (s, r)
        return r
    if isinstance(s, LazySet):
        if isinstance(s, IntervalSet):
            return tuple(range(s.lo, s.hi + 1))
        if isinstance(s, PowerSet):
            return tuple(sorted(s.materialize(), key=tlc_key))
        return tuple(ENUM_WATCH.watched(s.iterate(), s.describe))
    raise EvalError(f"Attempted to enumerate a non-set value: {fmt(s)}")


def iter_set(s: Value) -> Iterable[Value]:
    """Elements in an unspecified order (for order-independent uses)."""
    if type(s) is frozenset:
        return s
    if isinstance(s, LazySet):
        if isinstance(s, IntervalSet):
            return range(s.lo, s.hi + 1)
        return s.materialize()
    raise EvalError(f"Attempted to enumerate a non-set value: {fmt(s)}")


# ----------------------------------------------------------------- kinds, equality


def kind(v: Value) -> str:
    t = type(v)
    if t is bool:
        return "boolean"
    if t is int:
        return "integer"
    if t is str:
        return "string"
    if t is ModelValue:
        return "model value"
    if t is tuple or t is FnValue:
        return "function"
    if t is frozenset or isinstance(v, LazySet):
        return "set"
    if callable(v):
        return "operator"
    return t.__name__


_SIMPLE = (int, str, bool)
# Key types for which Python's equality of two keys of the same type is TLA+'s.
_EXACT_KEYS = frozenset((int, str, ModelValue))
_CONTAINERS = (tuple, FnValue, frozenset)
CONTAINER_TYPES = _CONTAINERS  # the types whose Python equality can merge TRUE and 1 inside


def values_equal(a: Value, b: Value) -> bool:
    """TLA+ ``=``: TLC reports an error comparing values of different kinds, except
    model values (which differ from every other value), at any depth: ``<<1>> =
    <<TRUE>>`` is an error, not TRUE (Python's ``(1,) == (True,)``)."""
    ta = type(a)
    if ta is type(b):
        if ta is int or ta is str or ta is bool or ta is ModelValue:
            return a == b
        if ta in _CONTAINERS:
            if a == b:
                return same_kinds(a, b) or tlc_equals(a, b)
            return False if _unequal_plainly(a, b, ta) else tlc_equals(a, b)
        return a == b
    ka, kb = kind(a), kind(b)
    if ka == kb:
        if a == b:
            return same_kinds(a, b) or tlc_equals(a, b)
        return tlc_equals(a, b) if ka == "function" else False
    if ka == "model value" or kb == "model value":
        return False
    raise _equality_error(a, b)


_SIMPLE_SET = frozenset(_SIMPLE) | {ModelValue}


def _unequal_plainly(a: Value, b: Value, t: type) -> bool:
    """For Python-unequal `a` and `b` of type `t`: True when TLC's walk (`tlc_equals`)
    surely finds them unequal without comparing incomparable kinds (checked in C:
    different sizes, or the same simple types position by position)."""
    if t is tuple:
        return len(a) != len(b) or (_SIMPLE_SET.issuperset(map(type, a))
                                    and tuple(map(type, a)) == tuple(map(type, b)))
    if t is FnValue:
        da, db = a.d, b.d
        if len(da) != len(db):
            return not _record_against_non_record(a, b)
        if type(next(iter(da), "")) is str and list(da) == list(db):
            va, vb = da.values(), db.values()
            return _SIMPLE_SET.issuperset(map(type, va)) and list(map(type, va)) == list(map(type, vb))
        return False
    if len(a) != len(b):
        return True
    ts = set(map(type, a))
    return len(ts) == 1 and ts <= _SIMPLE_SET and ts == set(map(type, b))


def _equality_error(a: Value, b: Value) -> EvalError:
    """TLC's message where ``a.equals(b)`` meets values of incomparable kinds (each
    value class of TLC words it its own way)."""
    ka = kind(a)
    if ka == "function":
        if type(a) is FnValue and a.d and all(type(k) is str for k in a.d):
            return EvalError(f"Attempted to check equality of record:\n{fmt(a)}\nwith non-record\n{fmt(b)}")
        return EvalError(f"Attempted to check equality of the function {fmt(a)} with the value:\n{fmt(b)}")
    if ka == "set":
        return EvalError(f"Attempted to check equality of the set {fmt(a)} with the value:\n{fmt(b)}")
    verb = "compare equality" if ka == "boolean" else "check equality"
    return EvalError(f"Attempted to {verb} of {ka} {fmt(a)} with non-{ka}:\n{fmt(b)}")


def _compare_error(a: Value, b: Value) -> EvalError:
    """TLC's message where ``a.compareTo(b)`` (sorting a set, a binary search in one)
    meets values of incomparable kinds."""
    ka = kind(a)
    if ka in ("boolean", "integer", "string"):
        return EvalError(f"Attempted to compare {ka} {fmt(a)} with non-{ka}:\n{fmt(b)}")
    if ka == "function":
        return EvalError(f"Attempted to compare the function {fmt(a)} with the value:\n{fmt(b)}")
    return EvalError(f"Attempted to compare the set {fmt(a)} with the value:\n{fmt(b)}")


def tlc_fn_items(f: Value) -> list:
    """A function's (key, value) pairs in TLC's order of its domain."""
    if type(f) is tuple:
        return list(zip(range(1, len(f) + 1), f))
    keys = sorted(f.d, key=tlc_key)
    return [(k, f.d[k]) for k in keys]


def tlc_equals(a: Value, b: Value) -> bool:
    """``a.equals(b)`` as TLC computes it: the same walk in the same order (a tuple's
    length first, a record's field names, a function's domain in TLC's order, a set's
    size then its elements in TLC's order), so that the first pair of incomparable
    kinds it meets raises TLC's error, wherever Python would answer."""
    ta, tb = type(a), type(b)
    if ta is ModelValue or tb is ModelValue:
        return a is b
    ka, kb = kind(a), kind(b)
    if ka != kb:
        raise _equality_error(a, b)
    if ka != "function" and ka != "set":
        return a == b
    if ka == "set":
        if not (is_finite(a) and is_finite(b)):
            return a == b
        if set_size(a) != set_size(b):
            return False
        return all(tlc_equals(x, y) for x, y in zip(sorted_elems(a), sorted_elems(b)))
    if ta is tuple and tb is tuple:
        return len(a) == len(b) and all(tlc_equals(x, y) for x, y in zip(a, b))
    if _record_against_non_record(a, b):
        raise EvalError(f"Attempted to check equality of record:\n{fmt(a)}\nwith non-record\n{fmt(b)}")
    ia, ib = tlc_fn_items(a), tlc_fn_items(b)
    if len(ia) != len(ib):
        return False
    if ta is FnValue and tb is FnValue and all(type(k) is str for k, _ in ia):
        # A record: its field names first (TLC's RecordValue.equals).
        if [k for k, _ in ia] != [k for k, _ in ib]:
            return False
    else:
        for (x, _), (y, _) in zip(ia, ib):
            if not tlc_equals(x, y):
                return False
    return all(tlc_equals(x, y) for (_, x), (_, y) in zip(ia, ib))


def _record_against_non_record(a: Value, b: Value) -> bool:
    """TLC's RecordValue.equals(b): `a` a record and `b` a function that is not one (a
    domain other than field names), an error whatever the sizes; ``<<>>`` is the empty record."""
    if type(a) is not FnValue or not a.d or not all(type(k) is str for k in a.d):
        return False
    if type(b) is tuple:
        return len(b) > 0
    return type(b) is FnValue and not all(type(k) is str for k in b.d)


def same_kinds(a: Value, b: Value) -> bool:
    """For Python-equal `a` and `b`: True only if they are the same TLA+ value (no TRUE
    where the other has 1, at any depth).  Cheap and conservative: False may also mean
    "cannot tell quickly" (then compare `exact_key`s)."""
    if a is b:
        return True
    t = type(a)
    if t is not type(b):
        return False
    if t is tuple:
        # Only the positions holding different objects are looked at (in C, `compress`).
        for x, y in compress(zip(a, b), map(is_not, a, b)):
            tx = type(x)
            if tx is not type(y) or (tx in _CONTAINERS and not same_kinds(x, y)):
                return False
        return True
    if t is FnValue:
        return _same_entries(a.d, b.d)
    if t is frozenset:
        ta = set(map(type, a))
        if len(ta) != 1:
            return not a
        te = next(iter(ta))
        if te is str or te is ModelValue:
            return True  # their Python equality is TLA+'s: b's elements have the type too
        if ta != set(map(type, b)):
            return False
        if te is int or te is bool:
            return True
        # Equal sets built alike iterate alike; otherwise pair the elements up.
        for x, y in zip(a, b):
            if x is not y:
                if x != y:
                    break
                if not same_kinds(x, y):
                    return False
        else:
            return True
        pair = {y: y for y in b}
        for x in a:
            y = pair[x]
            if x is not y and not same_kinds(x, y):
                return False
        return True
    return True


def _same_entries(da: dict, db: dict) -> bool:
    """For Python-equal dicts of two functions: the same keys and values to TLA+."""
    if all(map(is_, da, db)):
        va, vb = da.values(), db.values()
        for x, y in compress(zip(va, vb), map(is_not, va, vb)):
            tx = type(x)
            if tx is not type(y) or (tx in _CONTAINERS and not same_kinds(x, y)):
                return False
        return True
    # Another order of the same keys: pair them up (a key may be 1 here, TRUE there).
    kt = set(map(type, da))
    if not (kt <= _EXACT_KEYS and kt == set(map(type, db))):
        pair = {k: k for k in db}
        for k in da:
            kb = pair[k]
            if k is not kb and not same_kinds(k, kb):
                return False
    for k, x in da.items():
        y = db[k]
        if x is not y:
            tx = type(x)
            if tx is not type(y) or (tx in _CONTAINERS and not same_kinds(x, y)):
                return False
    return True


class _BoolKey:
    """TRUE or FALSE inside an `exact_key`: equal to nothing but itself."""

    __slots__ = ("v",)

    def __init__(self, v: bool) -> None:
        self.v = v

    def __reduce__(self) -> tuple:
        return (_bool_key, (self.v,))

    def __repr__(self) -> str:
        return "TRUE" if self.v else "FALSE"


_TRUE_KEY, _FALSE_KEY = _BoolKey(True), _BoolKey(False)
_FN_TAG = "\x00fn"


def _bool_key(v: bool) -> _BoolKey:
    return _TRUE_KEY if v else _FALSE_KEY


def exact_key(v: Value) -> Any:
    """A key whose Python equality and hash are TLA+ equality: `v` with every boolean
    replaced by a key equal to no integer.  A full walk of `v`."""
    t = type(v)
    if t is bool:
        return _TRUE_KEY if v else _FALSE_KEY
    if t is int or t is str or t is ModelValue:
        return v
    if t is tuple:
        return tuple(map(exact_key, v))
    if t is FnValue:
        return (_FN_TAG, frozenset((exact_key(k), exact_key(x)) for k, x in v.d.items()))
    if t is frozenset:
        return frozenset(map(exact_key, v))
    if isinstance(v, LazySet):
        return frozenset(map(exact_key, v.materialize())) if v.finite else (type(v).__name__, v.describe())
    return v


def kind_signature(v: Value) -> Any:
    """The kinds inside `v`, position by position: two values with one signature are
    compared by TLC (sorting, ``=``) without meeting values of incomparable kinds.  None
    where that cannot be told this way (model values, lazy sets, a set whose elements
    differ in shape, a function over compound values)."""
    t = type(v)
    if t is int or t is str or t is bool:
        return t
    if t is tuple:
        return (tuple, tuple(map(kind_signature, v)))
    if t is FnValue:
        d = v.d
        kt = set(map(type, d))
        if kt == {str}:  # a record: its fields by name
            return (FnValue, frozenset((k, kind_signature(x)) for k, x in d.items()))
        if kt == {int} or kt == {bool}:  # TLC compares the domains in this order
            return (FnValue, tuple((type(k), kind_signature(d[k])) for k in sorted(d)))
        return None
    if t is frozenset:
        inner = set(map(kind_signature, v))
        if len(inner) > 1 or None in inner:
            return None
        return (frozenset, inner.pop() if inner else ())
    return None


def uniform_kinds(elems: Iterable[Value]) -> bool:
    """True when all `elems` have one (known) kind signature: any comparison TLC makes
    between them pairs values of one kind."""
    sigs = set(map(kind_signature, elems))
    return len(sigs) <= 1 and None not in sigs


def check_set_kinds(elems: list, s: frozenset) -> frozenset:
    """The set `s` built from `elems`, or TLC's error where sorting them (TLC normalises
    every set it compares, stores or counts) compares values of incomparable kinds:
    ``{1, TRUE}`` is an error, not a one-element set, and so are ``{<<1>>, <<TRUE>>}``
    (which Python merges) and ``{[a |-> 1], (2 :> 1)}`` (a field name against 2).
    Compounds of one kind signature need no sorting."""
    types = set(map(type, elems))
    if len(types) == 1:
        t = types.pop()
        if t in _SIMPLE or t is ModelValue or len(elems) < 2:
            return s
        if (len(s) == len(elems) or len(set(map(exact_key, elems))) == len(s)) and uniform_kinds(elems):
            return s
    else:
        types.discard(ModelValue)
        if len(types) <= 1:
            return s
    _tlc_sort(elems)
    return s


def check_same_kind_sets(a: frozenset, b: frozenset, op: str) -> None:
    """``a \\cup b``, ``a \\cap b``, ``a \\ b`` on sets whose elements TLC cannot compare
    (``{1} \\cup {TRUE}``): its error."""
    if not a or not b:
        return
    ta, tb = type(next(iter(a))), type(next(iter(b)))
    if ta is ModelValue or tb is ModelValue:
        return
    if ta is tb and ta not in _CONTAINERS:
        return
    if (ta in _CONTAINERS and tb in _CONTAINERS and (ta is frozenset) is (tb is frozenset)
            and uniform_kinds(chain(a, b))):
        return
    # TLC looks each element of one set up in the other (`x.equals(y)` along a set
    # literal, which it keeps unsorted): for \\cup an element of `b` in `a`, for \\cap
    # and \\ an element of `a` in `b`.
    x, y = (a, b) if op == "\\cup" else (b, a)
    for e in sorted_elems(y):
        for f in sorted_elems(x):
            if tlc_equals(f, e):  # raises TLC's error for incomparable kinds
                break


def _tlc_compare(a: Value, b: Value) -> int:
    """``a.compareTo(b)`` as TLC: an error for values of incomparable kinds."""
    if type(a) is ModelValue or type(b) is ModelValue:
        if a is b:
            return 0
        if type(a) is ModelValue and type(b) is ModelValue:
            return -1 if string_rank(a.name) < string_rank(b.name) else 1
        return -1 if type(a) is ModelValue else 1
    ka, kb = kind(a), kind(b)
    if ka != kb:
        raise _compare_error(a, b)
    if ka == "set":
        ea, eb = _tlc_sort(list(iter_set(a))), _tlc_sort(list(iter_set(b)))
        if len(ea) != len(eb):
            return len(ea) - len(eb)
        for x, y in zip(ea, eb):
            c = _tlc_compare(x, y)
            if c:
                return c
        return 0
    if ka == "function":
        if _record_against_non_record(a, b):  # RecordValue.compareTo, whatever the sizes
            raise EvalError(f"Attempted to compare record:\n{fmt(a)}\nwith non-record\n{fmt(b)}")
        ia, ib = tlc_fn_items(a), tlc_fn_items(b)
        if len(ia) != len(ib):
            return len(ia) - len(ib)
        for (x, _), (y, _) in zip(ia, ib):
            c = _tlc_compare(x, y)
            if c:
                return c
        for (_, x), (_, y) in zip(ia, ib):
            c = _tlc_compare(x, y)
            if c:
                return c
        return 0
    ta, tb = tlc_key(a), tlc_key(b)
    return -1 if ta < tb else (1 if ta > tb else 0)


def _tlc_sort(elems: list) -> list:
    """TLC's ValueVec.sort(true): a binary insertion sort without duplicates, with its
    comparisons in its order (so that the first incomparable pair raises its error)."""
    out: list = []
    for i, elem in enumerate(elems):
        if i == 0:
            out.append(elem)
            continue
        low, high, cmp, idx = 0, len(out), 0, 0
        while low < high:
            idx = (low + high) >> 1
            cmp = _tlc_compare(elem, out[idx])
            if cmp == 0:
                break
            if cmp < 0:
                high = idx
            else:
                low = idx + 1
        if cmp != 0:
            out.insert(idx if cmp < 0 else idx + 1, elem)
    return out


def member_kind_check(v: Value, s: frozenset) -> None:
    """Raise TLC's error if looking `v` up in the finite set `s` compares values of
    incomparable kinds (TLC's binary search in its sorted elements): ``1 \\in BOOLEAN``."""
    tlc_search(v, s)


def tlc_search(v: Value, s: frozenset) -> bool:
    """``v \\in s`` by TLC's binary search in the sorted elements of `s`: TLC's error at a
    pair of incomparable kinds it compares, else whether an element compared equal."""
    if not s:
        return False
    tv = type(v)
    if tv is ModelValue:
        return v in s
    kv = kind(v)
    elems = sorted_elems(s)
    low, high = 0, len(elems)
    while low < high:
        mid = (low + high) >> 1
        e = elems[mid]
        if type(e) is not ModelValue and kind(e) != kv:
            raise _compare_error(v, e)
        cmp = _tlc_compare(v, e)
        if cmp == 0:
            return True
        if cmp < 0:
            high = mid
        else:
            low = mid + 1
    return False


# ----------------------------------------------------------------- printing


def fmt(v: Value) -> str:
    """TLC's printed form of a value."""
    t = type(v)
    if t is bool:
        return "TRUE" if v else "FALSE"
    if t is int:
        return str(v)
    if t is str:
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    if t is ModelValue:
        return v.name
    if t is tuple:
        return "<<" + ", ".join(fmt(x) for x in v) + ">>"
    if t is FnValue:
        keys = sorted(v.d, key=tlc_key)
        if all(type(k) is str for k in keys):
            return "[" + ", ".join(f"{k} |-> {fmt(v.d[k])}" for k in keys) + "]"
        return "(" + " @@ ".join(f"{fmt(k)} :> {fmt(v.d[k])}" for k in keys) + ")"
    if t is frozenset:
        return "{" + ", ".join(fmt(x) for x in sorted_elems(v)) + "}"
    if isinstance(v, LazySet):
        return v.describe()
    if callable(v):
        return "<operator>"
    return repr(v)
