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
    """Predicate number `index` of the formula's `atoms` (negated if `negated`): a state
    predicate, or (`action`) a step predicate ``[A]_v`` / ``<<A>>_v`` of the step
    from this state to the next."""

    index: int
    negated: bool = False
    action: bool = False


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
        return Atom(f.index, not f.negated, f.action)
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


def is_temporal(f: Formula) -> bool:
    if isinstance(f, (Always, Eventually, Next)):
        return True
    return isinstance(f, (And, Or)) and any(is_temporal(x) for x in f.items)


def has_action(f: Formula) -> bool:
    if isinstance(f, Atom):
        return f.action
    if isinstance(f, (And, Or)):
        return any(has_action(x) for x in f.items)
    return isinstance(f, (Always, Eventually, Next)) and has_action(f.arg)


def disjuncts(f: Formula, limit: int = 4096) -> list[list[Formula]] | None:
    """f in disjunctive normal form over its temporal subformulas and atoms, as TLC's
    `toDNF` (a list of conjunctions); None when it has more than `limit` disjuncts."""
    if isinstance(f, Or):
        out: list[list[Formula]] = []
        for x in f.items:
            part = disjuncts(x, limit)
            if part is None or len(out) + len(part) > limit:
                return None
            out.extend(part)
        return out
    if isinstance(f, And):
        acc: list[list[Formula]] = [[]]
        for x in f.items:
            part = disjuncts(x, limit)
            if part is None or len(acc) * len(part) > limit:
                return None
            acc = [a + b for a in acc for b in part]
        return acc
    return [[f]]


def without_tableau(f: Formula) -> bool:
    """Is f one of the conjuncts TLC checks on the behaviour graph without a tableau
    (`Liveness.classifyExpr`): ``<>[]A`` or ``[]<>A`` with A a state or step predicate?"""
    return (isinstance(f, (Always, Eventually)) and isinstance(f.arg, (Always, Eventually))
            and type(f.arg) is not type(f) and not is_temporal(f.arg.arg))


def holds_on_lasso(f: Formula, atoms: list[list[bool]], loop: int) -> bool:
    """Does the behaviour 0, 1, ..., n-1, then back to `loop` (forever) satisfy f at
    its start?  ``atoms[i][k]`` is the value of atom k in state i (for a step
    predicate: on the step from state i to the next)."""
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
