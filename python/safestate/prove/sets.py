"""Symbolic finite and infinite sets.

`EnumSet` is a finite list of (guard, element): the element is in the set when
its guard holds.  Guards let a set depend on the state or on a symbolic constant
(a CONSTANT that is any subset of a finite set gets one fresh Boolean per
element).  `PredSet` is a set known only by its membership predicate (``Nat``,
``a..b`` with symbolic bounds, ``[f : S]``, ``Seq(S)``...): it can be tested for
membership and give a fresh element of its shape, but not be enumerated.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

import z3

from ..tla.errors import Loc
from .values import ProveError, eq, fresh_like, or_, value_key


class SetV:
    def member(self, x: Any, loc: Loc | None = None) -> z3.BoolRef:
        raise NotImplementedError

    def fresh(self, name: str, loc: Loc | None = None) -> Any:
        raise NotImplementedError


@dataclass(eq=False)
class EnumSet(SetV):
    items: list[tuple[z3.BoolRef, Any]]
    # a representative element when the set may be empty (for fresh())
    shape: Any = None
    # DOMAIN of a bounded sequence: the set is 1..prefix_len (a function over it is a sequence)
    prefix_len: Any = None
    _index: Any = field(default=False, init=False, repr=False)   # see _by_key
    _shape: Any = field(default=None, init=False, repr=False)

    def member(self, x: Any, loc: Loc | None = None) -> z3.BoolRef:
        k = value_key(x)
        if k is not None:
            by_key = self._by_key()
            if by_key is not None and (not by_key or k[0] == self._shape):
                # a concrete element met by concrete elements of its shape: found by its
                # key, not by an equality per element (most of the press's membership
                # tests: a state name in a set of state names)
                return or_(by_key.get(k[1], []))
        return z3.Or([z3.And(g, eq(x, e, loc)) for g, e in self.items])

    def _by_key(self) -> dict[Any, list[z3.BoolRef]] | None:
        """The guards of the elements by value key, when every element is concrete and of
        one shape (None otherwise; the elements are never changed once the set is made)."""
        if self._index is False:
            by: dict[Any, list[z3.BoolRef]] | None = {}
            shape = None
            for g, e in self.items:
                k = value_key(e)
                if k is None or (shape is not None and k[0] != shape):
                    by = None
                    break
                shape = k[0]
                by.setdefault(k[1], []).append(g)  # type: ignore[union-attr]
            self._index, self._shape = by, shape
        return self._index  # type: ignore[return-value]

    def fresh(self, name: str, loc: Loc | None = None) -> Any:
        proto = self.items[0][1] if self.items else self.shape
        if proto is None:
            raise ProveError("cannot infer the element shape of an empty set", loc)
        return fresh_like(proto, name)

    def all_certain(self) -> bool:
        return all(z3.is_true(g) for g, _ in self.items)


@dataclass(eq=False)
class PredSet(SetV):
    desc: str
    pred: Callable[[Any], z3.BoolRef]
    maker: Callable[[str], Any]
    # for integer sets: a concrete upper bound when one is known (sequence capacities)
    upper: int | None = None
    extra: dict = field(default_factory=dict)

    def member(self, x: Any, loc: Loc | None = None) -> z3.BoolRef:
        return self.pred(x)

    def fresh(self, name: str, loc: Loc | None = None) -> Any:
        return self.maker(name)


def need_enum(s: Any, what: str, loc: Loc | None) -> EnumSet:
    if isinstance(s, EnumSet):
        return s
    if isinstance(s, PredSet):
        raise ProveError(f"{what} over the non-enumerable set {s.desc}", loc)
    raise ProveError(f"{what} over a value that is not a set", loc)


def need_set(s: Any, what: str, loc: Loc | None) -> SetV:
    if isinstance(s, SetV):
        return s
    raise ProveError(f"{what} of a value that is not a set", loc)


def set_ite(c: z3.BoolRef, a: SetV, b: SetV, loc: Loc | None) -> SetV:
    if isinstance(a, EnumSet) and isinstance(b, EnumSet):
        return EnumSet([(z3.And(c, g), e) for g, e in a.items] + [(z3.And(z3.Not(c), g), e) for g, e in b.items],
                       a.shape if a.shape is not None else b.shape)
    return PredSet("IF-set", lambda x: z3.If(c, a.member(x, loc), b.member(x, loc)),
                   lambda n: a.fresh(n, loc))


def set_eq(a: SetV, b: SetV, loc: Loc | None) -> z3.BoolRef:
    return z3.And(subseteq(a, b, loc), subseteq(b, a, loc))


def subseteq(a: SetV, b: SetV, loc: Loc | None) -> z3.BoolRef:
    ea = need_enum(a, "\\subseteq", loc)
    return z3.And([z3.Implies(g, b.member(e, loc)) for g, e in ea.items])


def union(a: SetV, b: SetV, loc: Loc | None) -> SetV:
    if isinstance(a, EnumSet) and isinstance(b, EnumSet):
        return EnumSet(a.items + b.items, a.shape if a.shape is not None else b.shape)
    proto = a if isinstance(a, PredSet) or (isinstance(a, EnumSet) and a.items) else b
    return PredSet("union", lambda x: z3.Or(a.member(x, loc), b.member(x, loc)), lambda n: proto.fresh(n, loc))


def intersect(a: SetV, b: SetV, loc: Loc | None) -> SetV:
    if isinstance(a, EnumSet):
        return EnumSet([(z3.And(g, b.member(e, loc)), e) for g, e in a.items], a.shape)
    if isinstance(b, EnumSet):
        return intersect(b, a, loc)
    return PredSet("intersection", lambda x: z3.And(a.member(x, loc), b.member(x, loc)), lambda n: a.fresh(n, loc),
                   upper=a.upper if isinstance(a, PredSet) else None)


def difference(a: SetV, b: SetV, loc: Loc | None) -> SetV:
    if isinstance(a, EnumSet):
        return EnumSet([(z3.And(g, z3.Not(b.member(e, loc))), e) for g, e in a.items], a.shape)
    return PredSet(f"{getattr(a, 'desc', 'set')} \\ ...", lambda x: z3.And(a.member(x, loc), z3.Not(b.member(x, loc))),
                   lambda n: a.fresh(n, loc), upper=a.upper if isinstance(a, PredSet) else None)


def filter_set(s: SetV, pred: Callable[[Any], z3.BoolRef], loc: Loc | None) -> SetV:
    if isinstance(s, EnumSet):
        return EnumSet([(z3.And(g, pred(e)), e) for g, e in s.items], s.shape)
    assert isinstance(s, PredSet)
    return PredSet(f"{{x \\in {s.desc} : ...}}", lambda x: z3.And(s.member(x, loc), pred(x)),
                   lambda n: s.fresh(n, loc), upper=s.upper)


def cardinality(s: EnumSet, loc: Loc | None) -> z3.ArithRef:
    """Cardinality of an enumerated set: elements equal to an earlier present one do not count."""
    terms = []
    for i, (g, e) in enumerate(s.items):
        dup = [z3.And(g2, eq(e2, e, loc)) for g2, e2 in s.items[:i]]
        counted = z3.And(g, z3.Not(z3.Or(dup))) if dup else g
        terms.append(z3.If(counted, z3.IntVal(1), z3.IntVal(0)))
    return z3.simplify(z3.Sum(terms)) if terms else z3.IntVal(0)
