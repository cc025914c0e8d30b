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
from typing import Union

import z3

from ..tla.errors import Loc


Guard = Union[z3.BoolRef, Callable[[], z3.BoolRef]]  # a callable: built only if some obligation needs it


@dataclass(eq=False)
class Obligation:
    kind: str          # domain | field | choose | division | sequence | case | capacity | type
    loc: Loc | None
    what: str          # what must hold, in words
    site: z3.BoolRef   # the condition at the site itself
    # the path conditions around it, as a shared chain (outermost guard, the rest) or ():
    # not a z3 term, since wrapping every obligation at every level through z3py
    # dominated the translation of the state-chain press
    guards: tuple = ()
    _cond: z3.BoolRef | None = field(default=None, repr=False)

    @property
    def cond(self) -> z3.BoolRef:
        """holds in every state (and step) where the site is evaluated"""
        if self._cond is None:
            gs, chain = [], self.guards
            while chain:
                gs.append(chain[0])
                chain = chain[1]
            self._cond = z3.Implies(z3.And(gs), self.site) if gs else self.site
        return self._cond

    def where(self) -> str:
        return f"{self.loc.file}:{self.loc.line}:{self.loc.column}" if self.loc else "?"


class Obligations:
    """The obligations of the expression being translated, under the current path condition."""

    def __init__(self) -> None:
        self.items: list[Obligation] = []

    def add(self, kind: str, loc: Loc | None, what: str, cond: z3.BoolRef | bool) -> None:
        c = z3.BoolVal(cond) if isinstance(cond, bool) else cond
        if not (z3.is_true(c) or z3.is_false(c)):
            c = z3.simplify(c)  # most sites are concrete: their obligation folds to TRUE
        if z3.is_true(c):
            return
        self.items.append(Obligation(kind, loc, what, c))

    def emit(self, obligations: list[Obligation]) -> None:
        self.items.extend(obligations)

    def take(self) -> list[Obligation]:
        """The obligations collected so far (and a fresh, empty collection)."""
        out, self.items = self.items, []
        return out

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
                    saved.extend(inner if z3.is_true(g) else _under(_unique(inner), g))

    @contextmanager
    def capture(self) -> Iterator[list[Obligation]]:
        """Collect the obligations added inside into the yielded list, not into this collection."""
        saved, self.items = self.items, []
        out: list[Obligation] = []
        try:
            yield out
        finally:
            out.extend(self.items)
            self.items = saved


def _under(obligations: list[Obligation], g: z3.BoolRef) -> list[Obligation]:
    """The obligations under one more guard; those sharing a chain share the new one."""
    chains: dict[int, tuple] = {}
    out = []
    for o in obligations:
        chain = chains.get(id(o.guards))
        if chain is None:
            chain = chains[id(o.guards)] = (g, o.guards)
        out.append(Obligation(o.kind, o.loc, o.what, o.site, chain))
    return out


def _unique(obligations: list[Obligation]) -> list[Obligation]:
    """Without repeats (a memoised operator re-emits the same obligations at every use)."""
    seen: set[tuple[int, int]] = set()
    out = []
    for o in obligations:
        key = (id(o.site), id(o.guards))
        if key not in seen:
            seen.add(key)
            out.append(o)
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
