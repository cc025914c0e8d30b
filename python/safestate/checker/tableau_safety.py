"""TLC's early stop at a finite counterexample of a temporal property.

TLC builds the behaviour graph (states x tableau nodes of the negated property)
while it explores the states (`LiveCheck.TableauLiveChecker.addNextState`).  When
the spec has no fairness and the negation has no ``<>[]A`` / ``[]<>A`` conjuncts
(`OrderOfSolution.hasEmptyPEM`), a node whose tableau successor at the same state is
the *accepting* node (the empty particle, a sink: every continuation violates the
property, e.g. after ``P /\\ ~Q`` for ``P => []Q``) ends the search at once: TLC
prints "Temporal property X was violated." with the finite behaviour leading there
(shortest path in the behaviour graph, stuttering dropped) and exits with 12, with
the counts of the moment: after the expansion of the state that completed it.

This module replays that construction on the explored graph, in TLC's order: the
states are expanded in BFS order; expanding s adds, for every node (s, t) recorded
so far, the steps to (s', t') for every successor s' of s and s itself (stuttering)
and every tableau successor t' consistent with s'; a new node of an already
expanded state is expanded at once (`addNextState` on a done state), and that is
where TLC looks for the accepting successor.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Callable

from . import ltl, tableau
from .temporal import Obligation


@dataclass
class SafetyStop:
    """The search stops after expanding state `expanded`; `states` is the printed behaviour."""

    obligation: Obligation
    expanded: int
    states: list[int]


def needs_no_cycle(ob: Obligation, fair: bool) -> bool:
    """Does TLC check this property for an early stop (no fairness, and its negation
    has no <>[]A / []<>A conjunct)?"""
    if fair or ob.formula is None:
        return False
    conjuncts = ltl.disjuncts(ltl.negate(ob.formula))
    return conjuncts is not None and not any(ltl.without_tableau(c) for d in conjuncts for c in d)


class _Replay:
    def __init__(self, tab: tableau.Tableau, states: list[tuple], atoms: list,
                 succ: Callable[[int], list[int]]) -> None:
        self.tab = tab
        self.states = states
        self.atoms = atoms
        self.succ = succ
        self.accepting = {i for i, p in enumerate(tab.particles) if not p.literals and not p.nexts}
        self.nodes: dict[int, list[int]] = {}          # state -> tableau nodes recorded
        self.edges: dict[tuple[int, int], list[tuple[int, int]]] = {}
        self.done: set[int] = set()
        self.error: tuple[int, int] | None = None
        self._consistent: dict[tuple[int, int], bool] = {}

    def consistent(self, t: int, s: int) -> bool:
        key = (t, s)
        c = self._consistent.get(key)
        if c is None:
            st = self.states[s]
            c = self._consistent[key] = all(bool(self.atoms[lit.index](st)) != lit.negated
                                            for lit in self.tab.particles[t].literals)
        return c

    def _record(self, node: tuple[int, int]) -> bool:
        """Records node; False if it was there already."""
        if node in self.edges:
            return False
        self.edges[node] = []
        self.nodes.setdefault(node[0], []).append(node[1])
        return True

    def init(self, s: int) -> None:
        for t in self.tab.initial:
            if self.consistent(t, s):
                self._record((s, t))

    def expand(self, s: int) -> None:
        """TLC's addNextState for a state the search has just expanded."""
        self.done.add(s)
        # TLC visits the successors in its hash set's order; stuttering first gives the
        # shortest behaviour where both complete a counterexample.
        targets = [s, *dict.fromkeys(x for x in self.succ(s) if x != s)]
        for t0 in list(self.nodes.get(s, ())):
            self._link((s, t0), targets, check_accepting=False)

    def _link(self, node: tuple[int, int], targets: list[int], check_accepting: bool) -> None:
        # An explicit stack instead of TLC's recursion (behaviour graphs are deep).
        work = [(node, iter(targets), check_accepting)]
        while work:
            (s, t), it, check = work[-1]
            pushed = False
            for s1 in it:
                for t1 in self.tab.successors[t]:
                    if not self.consistent(t1, s1):
                        continue
                    if check and s1 == s and t1 in self.accepting:
                        if self.error is None:
                            self.error = (s, t)
                        continue
                    new = (s1, t1)
                    self.edges[(s, t)].append(new)
                    if self._record(new) and s1 in self.done:
                        # The done-state case: its stuttering step first, then its successors.
                        work.append((new, iter([s1, *dict.fromkeys(x for x in self.succ(s1) if x != s1)]), True))
                        pushed = True
                if pushed:
                    break
            if not pushed:
                work.pop()

    def path(self, initial: list[tuple[int, int]]) -> list[int]:
        """The states of a shortest path from an initial node to the error node,
        stuttering dropped (`TableauDiskGraph.getPath`)."""
        assert self.error is not None
        prev: dict[tuple[int, int], tuple[int, int] | None] = {n: None for n in initial}
        dq = deque(initial)
        while dq:
            n = dq.popleft()
            if n == self.error:
                break
            for m in self.edges.get(n, ()):
                if m not in prev:
                    prev[m] = n
                    dq.append(m)
        out: list[int] = []
        cur: tuple[int, int] | None = self.error
        while cur is not None:
            if not out or out[-1] != cur[0]:
                out.append(cur[0])
            cur = prev[cur]
        out.reverse()
        return out


def first_stop(obligations: list[Obligation], fair: bool, states: list[tuple], initial: list[int],
               succ: Callable[[int], list[int]], expanded: int) -> SafetyStop | None:
    """The earliest stop TLC's search makes at one of the obligations (the first in
    .cfg order when several stop at the same state), among the first `expanded`
    expanded states."""
    best: SafetyStop | None = None
    for ob in obligations:
        if not needs_no_cycle(ob, fair):
            continue
        assert ob.formula is not None
        tab = tableau.build(ltl.negate(ob.formula))
        replay = _Replay(tab, states, ob.atoms, succ)
        if not replay.accepting:
            continue
        for s in initial:
            replay.init(s)
        init_nodes = [(s, t) for s in initial for t in replay.nodes.get(s, ())]
        limit = expanded if best is None else best.expanded
        for k in range(limit):
            replay.expand(k)
            if replay.error is not None:
                best = SafetyStop(ob, k, replay.path(init_nodes))
                break
    return best
