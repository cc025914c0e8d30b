"""The particle tableau of a temporal formula (Manna and Pnueli, "Temporal
Verification of Reactive Systems: Safety", section 5.5), as TLC builds it for the
negation of a property (`tlc2.tool.liveness.TBPar`, `TBGraph`).

A *particle* is what a formula demands of one state: the atoms that hold in it
(literals) and the formulas that must hold from the next state on.  The formula's
set is expanded by the alpha rules (``A /\\ B``: both; ``[]A``: A and ``()[]A``)
and the beta rules (``A \\/ B``: one of them; ``<>A``: A or ``()<>A``); a branch
with an atom and its negation is dropped.  The successors of a particle are the
particles of the set of its ``()`` formulas.  An infinite path through particles
whose states satisfy their literals satisfies the formula when it is *fulfilling*:
for every promise ``<>A`` it passes infinitely often through a particle that
fulfils it (contains A, or does not contain ``<>A``).  On a strongly connected
part of the product with the state graph this is: every promise is fulfilled by
one of its particles.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import ltl
from .ltl import Formula

# A tableau that large comes from a formula no property needs; refuse it clearly.
MAX_PARTICLES = 20000


@dataclass(frozen=True)
class Particle:
    literals: frozenset[ltl.Atom]
    nexts: frozenset[Formula]
    # Bit i set: the particle fulfils promise i of the tableau.
    fulfils: int


@dataclass
class Tableau:
    particles: list[Particle]
    initial: list[int]
    successors: list[list[int]]
    promises: list[ltl.Eventually]

    @property
    def all_fulfilled(self) -> int:
        return (1 << len(self.promises)) - 1


def _promises(f: Formula, out: list[ltl.Eventually]) -> None:
    if isinstance(f, ltl.Eventually) and f not in out:
        out.append(f)
    if isinstance(f, (ltl.And, ltl.Or)):
        for x in f.items:
            _promises(x, out)
    elif isinstance(f, (ltl.Always, ltl.Eventually, ltl.Next)):
        _promises(f.arg, out)


class _Expander:
    def __init__(self, promises: list[ltl.Eventually]) -> None:
        self.promises = promises
        self.memo: dict[frozenset[Formula], list[Particle]] = {}

    def particles(self, formulas: frozenset[Formula]) -> list[Particle]:
        """The particles of a set of formulas (all of them must hold now)."""
        found = self.memo.get(formulas)
        if found is None:
            out: dict[Particle, None] = {}
            self._expand(list(formulas), set(), set(), set(), out)
            found = self.memo[formulas] = list(out)
        return found

    def _expand(self, todo: list[Formula], seen: set[Formula], literals: set[ltl.Atom],
                nexts: set[Formula], out: dict[Particle, None]) -> None:
        while todo:
            f = todo.pop()
            if f in seen:
                continue
            seen.add(f)
            if isinstance(f, ltl.Const):
                if not f.value:
                    return
            elif isinstance(f, ltl.Atom):
                if ltl.Atom(f.index, not f.negated, f.action) in literals:
                    return
                literals.add(f)
            elif isinstance(f, ltl.And):
                todo.extend(f.items)
            elif isinstance(f, ltl.Always):
                todo.append(f.arg)
                nexts.add(f)
            elif isinstance(f, ltl.Next):
                nexts.add(f.arg)
            else:  # a beta rule: one branch per alternative
                options = f.items if isinstance(f, ltl.Or) else (f.arg, ltl.Next(f))
                for option in options:
                    self._expand([*todo, option], set(seen), set(literals), set(nexts), out)
                return
        fulfils = 0
        for i, p in enumerate(self.promises):
            if p not in seen or p.arg in seen:
                fulfils |= 1 << i
        out[Particle(frozenset(literals), frozenset(nexts), fulfils)] = None


def build(formula: Formula) -> Tableau:
    """The tableau of `formula` (in negation normal form): its particles, the initial
    ones (those of the formula itself) and each one's successors."""
    promises: list[ltl.Eventually] = []
    _promises(formula, promises)
    expander = _Expander(promises)
    index: dict[Particle, int] = {}
    particles: list[Particle] = []
    successors: list[list[int]] = []

    def number(p: Particle) -> int:
        i = index.get(p)
        if i is None:
            if len(particles) >= MAX_PARTICLES:
                raise OverflowError(f"the tableau has more than {MAX_PARTICLES} particles")
            i = index[p] = len(particles)
            particles.append(p)
            successors.append([])
        return i

    initial = [number(p) for p in expander.particles(frozenset([formula]))]
    i = 0
    while i < len(particles):
        successors[i] = [number(p) for p in expander.particles(particles[i].nexts)]
        i += 1
    return Tableau(particles, initial, successors, promises)
