"""Well-definedness obligations: the conditions under which a TLA+ expression has a value.

TLC stops with an evaluation error where TLA+ leaves a value unspecified: a function
applied outside its domain, a CHOOSE with no witness, ``a \\div 0``, Head of ``<< >>``,
a record without the field.  The translation gives such a site *some* value and records
here the condition under which it is evaluated correctly, relative to the path condition
of the site (TLA+ evaluates ``/\\``, ``\\/``, ``=>`` and IF left to right and stops early,
so ``x \\in DOMAIN f /\\ f[x] = 1`` obliges nothing).  docs/prove.md, "Well-definedness".
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, Union

import z3
from z3 import z3core as C
from z3.z3types import Ast

from ..tla.errors import Loc


Guard = Union[z3.BoolRef, Callable[[], z3.BoolRef]]  # a callable: built only if some obligation needs it


class Chain:
    """Path conditions as a shared linked chain (outermost guard first): the obligations
    wrapped by one guard share one link, and the conjunction of a chain is built once
    and shared by every obligation under it (rebuilding it per obligation through z3py
    dominated the translation of the state-chain press, whose 494,048 obligations sit
    under dozens of guards)."""

    __slots__ = ("guard", "rest", "_conj")

    def __init__(self, guard: z3.BoolRef, rest: "Chain | None") -> None:
        self.guard, self.rest, self._conj = guard, rest, None

    def conj(self) -> z3.BoolRef:
        """guard /\\ (the rest's conjunction); built iteratively (chains are deep)."""
        todo: list[Chain] = []
        c: Chain | None = self
        while c is not None and c._conj is None:
            todo.append(c)
            c = c.rest
        for link in reversed(todo):
            link._conj = link.guard if link.rest is None else _and2(link.guard, link.rest._conj)
        assert self._conj is not None
        return self._conj


# Through the C API: z3py's And/Implies coerce and sort-check every argument, which cost
# most of the press's translation (hundreds of thousands of obligations).
def _and2(a: z3.BoolRef, b: z3.BoolRef) -> z3.BoolRef:
    args = (Ast * 2)(a.as_ast(), b.as_ast())
    return z3.BoolRef(C.Z3_mk_and(a.ctx.ref(), 2, args), a.ctx)


def conjunction(fs: list[z3.BoolRef]) -> z3.BoolRef:
    """z3.And(fs), for the long lists of obligation conditions."""
    if not fs:
        return z3.BoolVal(True)
    args = (Ast * len(fs))(*(f.as_ast() for f in fs))
    return z3.BoolRef(C.Z3_mk_and(fs[0].ctx.ref(), len(fs), args), fs[0].ctx)


def _implies(a: z3.BoolRef, b: z3.BoolRef) -> z3.BoolRef:
    return z3.BoolRef(C.Z3_mk_implies(a.ctx.ref(), a.as_ast(), b.as_ast()), a.ctx)


@dataclass(eq=False)
class Obligation:
    kind: str          # domain | field | choose | division | sequence | case | capacity | type
    loc: Loc | None
    what: str          # what must hold, in words
    site: z3.BoolRef   # the condition at the site itself
    guards: Chain | None = None   # the path conditions around it (not a z3 term: shared, see Chain)
    _cond: z3.BoolRef | None = field(default=None, repr=False)

    @property
    def cond(self) -> z3.BoolRef:
        """holds in every state (and step) where the site is evaluated"""
        if self._cond is None:
            self._cond = self.site if self.guards is None else _implies(self.guards.conj(), self.site)
        return self._cond

    def where(self) -> str:
        return f"{self.loc.file}:{self.loc.line}:{self.loc.column}" if self.loc else "?"


class Obligations:
    """The obligations of the expression being translated, under the current path condition."""

    def __init__(self) -> None:
        self.items: list[Any] = []  # Obligation | _Under

    def add(self, kind: str, loc: Loc | None, what: str, cond: z3.BoolRef | bool) -> None:
        c = z3.BoolVal(cond) if isinstance(cond, bool) else cond
        if not (z3.is_true(c) or z3.is_false(c)):
            c = z3.simplify(c)  # most sites are concrete: their obligation folds to TRUE
        if z3.is_true(c):
            return
        self.items.append(Obligation(kind, loc, what, c))

    def emit(self, obligations: list[Any]) -> None:
        self.items.extend(obligations)

    def take(self) -> list[Obligation]:
        """The obligations collected so far (and a fresh, empty collection)."""
        out, self.items = self.items, []
        return flatten(out)

    @contextmanager
    def under(self, guard: Guard) -> Iterator[None]:
        """Obligations added inside hold only where `guard` does (a short-circuit)."""
        saved, self.items = self.items, []
        try:
            yield
        finally:
            inner, self.items = self.items, saved
            if inner:
                g = guard() if callable(guard) else guard
                if not z3.is_false(g):
                    # one node, not a copy of every inner obligation: an IF or CASE nests
                    # them many guards deep, and copying at each level cost O(n * depth)
                    if z3.is_true(g):
                        saved.extend(inner)
                    else:
                        saved.append(_Under(g, inner))

    @contextmanager
    def capture(self) -> Iterator[list[Any]]:
        """Collect the obligations added inside into the yielded list, not into this collection
        (it may hold guarded groups: `flatten` it to read the obligations one by one)."""
        saved, self.items = self.items, []
        out: list[Any] = []
        try:
            yield out
        finally:
            out.extend(self.items)
            self.items = saved


@dataclass(eq=False)
class _Under:
    """Obligations collected under one more path condition, kept as one node: `flatten`
    gives each of them its chain of guards once, at the end."""

    guard: z3.BoolRef
    inner: list  # Obligation | _Under


def _extend(guards: Chain | None, outer: Chain | None) -> Chain | None:
    """The guards of `guards` followed by those of `outer` (rarely needed: obligations
    are collected without guards and get them from the nodes around them)."""
    if guards is None:
        return outer
    links: list[z3.BoolRef] = []
    c: Chain | None = guards
    while c is not None:
        links.append(c.guard)
        c = c.rest
    out = outer
    for g in reversed(links):
        out = Chain(g, out)
    return out


def flatten(items: list) -> list[Obligation]:
    """The obligations of a collection, each under the guards of the nodes around it,
    without repeats (a memoised operator re-emits the same obligations, and the same
    nodes, at every use: each is visited once per chain of guards)."""
    out: list[Obligation] = []
    seen: set[tuple[int, int]] = set()
    # in collection order (a failing site is reported first where it was met first);
    # a stack of iterators, not recursion: the nodes nest as deep as the path conditions
    todo: list[tuple[Iterator[Any], Chain | None]] = [(iter(items), None)]
    while todo:
        group, chain = todo[-1]
        x = next(group, None)
        if x is None:
            todo.pop()
            continue
        key = (id(x.site) if isinstance(x, Obligation) else id(x), id(chain))
        if key in seen:
            continue
        seen.add(key)
        if isinstance(x, _Under):
            todo.append((iter(x.inner), Chain(x.guard, chain)))
        elif chain is None:
            out.append(x)
        else:
            out.append(Obligation(x.kind, x.loc, x.what, x.site, _extend(x.guards, chain)))
    return out


def distinct(obligations: list[Obligation]) -> list[Obligation]:
    """One obligation per (site, condition): a memoised operator re-emits its own at every use."""
    seen: set[tuple] = set()
    out = []
    for o in obligations:
        key = (o.loc.file if o.loc else None, o.loc.line if o.loc else 0, o.loc.column if o.loc else 0,
               o.cond.get_id())
        if key not in seen:
            seen.add(key)
            out.append(o)
    return out
