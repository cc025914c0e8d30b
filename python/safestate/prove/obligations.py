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


def _or(fs: list[z3.BoolRef]) -> z3.BoolRef:
    if len(fs) == 1:
        return fs[0]
    args = (Ast * len(fs))(*(f.as_ast() for f in fs))
    return z3.BoolRef(C.Z3_mk_or(fs[0].ctx.ref(), len(fs), args), fs[0].ctx)


def _implies(a: z3.BoolRef, b: z3.BoolRef) -> z3.BoolRef:
    return z3.BoolRef(C.Z3_mk_implies(a.ctx.ref(), a.as_ast(), b.as_ast()), a.ctx)


@dataclass(eq=False)
class Obligation:
    kind: str          # domain | field | choose | division | sequence | case | capacity | type
    loc: Loc | None
    what: str          # what must hold, in words
    site: z3.BoolRef   # the condition at the site itself
    path: z3.BoolRef | None = None   # where the site is evaluated (None: everywhere)
    _cond: z3.BoolRef | None = field(default=None, repr=False)

    @property
    def cond(self) -> z3.BoolRef:
        """holds in every state (and step) where the site is evaluated"""
        if self._cond is None:
            self._cond = self.site if self.path is None else _implies(self.path, self.site)
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


def flatten(items: list) -> list[Obligation]:
    """The obligations of a collection: one per site, under the disjunction of the path
    conditions it is met under (the conjunction of `path_i => site` over its paths).

    The collection is a DAG: a memoised operator re-emits the same nodes at every use,
    and an IF or CASE nests them many guards deep.  Each node gets its reach condition,
    the disjunction over the nodes that hold it of their own reach and guard, once, in
    topological order; an obligation per (site, path), as expanding the DAG into its
    tree gives, grew with the number of paths through the press's chain engine (GBs).
    The obligations come in collection order (a failing site is reported first where it
    was met first)."""
    root = _Under(z3.BoolVal(True), items)
    parents: dict[int, list[_Under]] = {id(root): []}
    nodes: dict[int, Any] = {id(root): root}
    first: list[Obligation] = []    # the leaves in collection order (pre-order, first visit)
    post: list[Any] = []            # every node after its children (a stack, not recursion: deep)
    todo: list[tuple[_Under, Iterator[Any]]] = [(root, iter(root.inner))]
    while todo:
        u, it = todo[-1]
        x = next(it, None)
        if x is None:
            todo.pop()
            post.append(u)
            continue
        ps = parents.get(id(x))
        if ps is not None:
            if not ps or ps[-1] is not u:
                ps.append(u)
            continue
        parents[id(x)] = [u]
        nodes[id(x)] = x
        if isinstance(x, _Under):
            todo.append((x, iter(x.inner)))
        else:
            post.append(x)
            first.append(x)
    # reach of a node: where it is evaluated; `inside` of an _Under: reach /\ guard
    inside: dict[int, z3.BoolRef | None] = {}   # None: TRUE
    reach: dict[int, z3.BoolRef | None] = {}
    for x in reversed(post):  # parents before children
        ps = parents[id(x)]
        if x is root:
            r: z3.BoolRef | None = None
        else:
            conds = _dedup([inside[id(p)] for p in ps])
            r = None if any(c is None for c in conds) else _or(conds)  # type: ignore[arg-type]
        reach[id(x)] = r
        if isinstance(x, _Under):
            g = x.guard
            inside[id(x)] = None if r is None and z3.is_true(g) else g if r is None else _and2(r, g)
    sites: dict[tuple, list[Obligation]] = {}
    for o in first:
        key = (o.loc.file if o.loc else None, o.loc.line if o.loc else 0, o.loc.column if o.loc else 0,
               o.kind, o.what, o.site.get_id())
        sites.setdefault(key, []).append(o)
    out: list[Obligation] = []
    for group in sites.values():
        o = group[0]
        paths = _dedup([_within(reach[id(x)], x.path) for x in group])
        path = None if any(p is None for p in paths) else _or(paths)  # type: ignore[arg-type]
        out.append(o if path is None and o.path is None else Obligation(o.kind, o.loc, o.what, o.site, path))
    return out


def _within(reach: z3.BoolRef | None, path: z3.BoolRef | None) -> z3.BoolRef | None:
    """An obligation's own path (obligations are made without one) inside its node's reach."""
    if path is None or reach is None:
        return reach if path is None else path
    return _and2(reach, path)


def _dedup(fs: list[z3.BoolRef | None]) -> list[z3.BoolRef | None]:
    seen: set[int] = set()
    out: list[z3.BoolRef | None] = []
    for f in fs:
        k = -1 if f is None else f.get_id()
        if k not in seen:
            seen.add(k)
            out.append(f)
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
