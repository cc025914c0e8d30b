"""Propositional temporal formulas over state predicates, as TLC's tableau method
takes them (`tlc2.tool.liveness.LiveExprNode` after `Liveness.astToLive`): atoms
(compiled state predicates), their negation, ``/\\``, ``\\/``, ``[]`` and ``<>``; the
next-state operator ``()`` appears only inside the tableau.  Negation is pushed to
the atoms (negation normal form), as TLC's `toDNF` does before building the tableau
of a property's negation."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Union


@dataclass(frozen=True)
class Atom:
    """State predicate number `index` of the formula's `atoms` (negated if `negated`)."""

    index: int
    negated: bool = False


@dataclass(frozen=True)
class Const:
    value: bool


@dataclass(frozen=True)
class And:
    items: tuple[Formula, ...]


@dataclass(frozen=True)
class Or:
    items: tuple[Formula, ...]


@dataclass(frozen=True)
class Always:
    arg: Formula


@dataclass(frozen=True)
class Eventually:
    arg: Formula


@dataclass(frozen=True)
class Next:
    """``()F``: F holds from the next state on (only built by the tableau)."""

    arg: Formula


Formula = Union[Atom, Const, And, Or, Always, Eventually, Next]


def negate(f: Formula) -> Formula:
    """~f in negation normal form (f is in it already)."""
    if isinstance(f, Atom):
        return Atom(f.index, not f.negated)
    if isinstance(f, Const):
        return Const(not f.value)
    if isinstance(f, And):
        return Or(tuple(negate(x) for x in f.items))
    if isinstance(f, Or):
        return And(tuple(negate(x) for x in f.items))
    if isinstance(f, Always):
        return Eventually(negate(f.arg))
    if isinstance(f, Eventually):
        return Always(negate(f.arg))
    return Next(negate(f.arg))  # () is self-dual on infinite behaviours


def holds_on_lasso(f: Formula, atoms: list[list[bool]], loop: int) -> bool:
    """Does the behaviour 0, 1, ..., n-1, then back to `loop` (forever) satisfy f at
    its start?  ``atoms[i][k]`` is the value of atom k in state i."""
    n = len(atoms)

    def successor(i: int) -> int:
        return i + 1 if i + 1 < n else loop

    def values(g: Formula) -> list[bool]:
        if isinstance(g, Atom):
            return [row[g.index] != g.negated for row in atoms]
        if isinstance(g, Const):
            return [g.value] * n
        if isinstance(g, (And, Or)):
            parts = [values(x) for x in g.items]
            join = all if isinstance(g, And) else any
            return [join(p[i] for p in parts) for i in range(n)]
        inner = values(g.arg)
        if isinstance(g, Next):
            return [inner[successor(i)] for i in range(n)]
        # From position i the behaviour visits i..n-1 and then the loop forever.
        join = all if isinstance(g, Always) else any
        return [join(inner[j] for j in range(min(i, loop), n)) for i in range(n)]

    return values(f)[0]
