"""A general temporal property checked as TLC does (`tlc2.tool.liveness`): the
tableau of its negation (`tableau.py`) times the state graph is the behaviour
graph; a strongly connected part of it that fulfils every promise of the tableau
and the spec's fairness is a behaviour of the spec violating the property.

A node of the behaviour graph is a pair (state, particle) whose state satisfies
the particle's state literals.  (s, t) -> (s', t') when s -> s' is a step or a
stuttering step (s' = s) that satisfies the step literals of t ([A]_v, <<A>>_v;
a stuttering step satisfies [A]_v and no <<A>>_v) and t' is a successor of t
in the tableau; the initial
nodes pair an initial state with an initial particle.  Stuttering steps cost
nothing in the search for the shortest prefix (0-1 BFS): they add no state to
the printed behaviour.  The component search, fairness and cycle are those of
`liveness.LivenessChecker`, on the behaviour graph; the lasso found is then
projected on the states (consecutive equal states merged).
"""

from __future__ import annotations

from array import array
from collections import deque
from typing import Callable, Iterable

from ..tla.errors import UnsupportedError
from . import ltl, tableau
from .liveness import Lasso, LivenessChecker, StateGraph
from .scc import strongly_connected
from .temporal import Fairness, Obligation


class BehaviourGraph:
    """The reachable part of the product of the state graph and a tableau, with the
    0-1 BFS distance (steps between distinct states) of every node from an initial one."""

    def __init__(self, graph: StateGraph, states: list[tuple], initial: list[int], tab: tableau.Tableau,
                 atoms: list, check_memory: Callable[[], None]) -> None:
        self.tableau = tab
        self.atoms = atoms
        self.states = states
        self._atom_values = bytearray(len(states) * len(atoms))  # 0 unknown, 1 false, 2 true
        self._step_values: dict[tuple[int, int, int], bool] = {}
        self._state_literals = [[lit for lit in p.literals if not lit.action] for p in tab.particles]
        self._step_literals = [[lit for lit in p.literals if lit.action] for p in tab.particles]
        self.state_of = array("i")
        self.particle_of = array("i")
        self.rows: list[list[int]] = []
        self.self_loop = bytearray()
        self.dist = array("q")
        self.parent = array("q")
        self.initial: list[int] = []
        index: dict[tuple[int, int], int] = {}

        def node(v: int, t: int) -> tuple[int, bool]:
            key = (v, t)
            i = index.get(key)
            if i is not None:
                return i, False
            i = index[key] = len(self.state_of)
            self.state_of.append(v)
            self.particle_of.append(t)
            self.rows.append([])
            self.self_loop.append(0)
            self.dist.append(-1)
            self.parent.append(-1)
            return i, True

        dq: deque[int] = deque()
        for v in initial:
            for t in tab.initial:
                if self.satisfies(v, t):
                    i, _ = node(v, t)
                    if self.dist[i] < 0:
                        self.dist[i] = 0
                        self.initial.append(i)
                        dq.append(i)
        # The successor particles of t that state w satisfies: the same (w, t) recurs
        # for every predecessor of w.
        consistent: dict[int, list[int]] = {}
        n_particles = len(tab.particles)
        done = bytearray()
        while dq:
            i = dq.popleft()
            if i < len(done) and done[i]:
                continue
            if len(done) < len(self.state_of):
                done.extend(bytes(len(self.state_of) - len(done)))
            done[i] = 1
            if i % 4096 == 0:
                check_memory()
            v, t = self.state_of[i], self.particle_of[i]
            row = self.rows[i]
            for w in (v, *graph.succ(v)):
                if not self.step_satisfies(v, w, t):
                    continue
                cost = 0 if w == v else 1
                key = w * n_particles + t
                nexts = consistent.get(key)
                if nexts is None:
                    nexts = consistent[key] = [t2 for t2 in tab.successors[t] if self.satisfies(w, t2)]
                for t2 in nexts:
                    j, _ = node(w, t2)
                    if j == i:
                        self.self_loop[i] = 1
                        continue
                    row.append(j)
                    d = self.dist[i] + cost
                    if self.dist[j] < 0 or self.dist[j] > d:
                        self.dist[j] = d
                        self.parent[j] = i
                        if cost:
                            dq.append(j)
                        else:
                            dq.appendleft(j)

    @property
    def n(self) -> int:
        return len(self.state_of)

    def satisfies(self, v: int, t: int) -> bool:
        """Does state v satisfy the state literals of particle t?"""
        k = len(self.atoms)
        for lit in self._state_literals[t]:
            c = v * k + lit.index
            if not self._atom_values[c]:
                self._atom_values[c] = 2 if self.atoms[lit.index](self.states[v]) else 1
            if (self._atom_values[c] == 2) == lit.negated:
                return False
        return True

    def step_satisfies(self, v: int, w: int, t: int) -> bool:
        """Does the step from state v to state w satisfy the step literals of particle t?"""
        for lit in self._step_literals[t]:
            key = (v, w, lit.index)
            value = self._step_values.get(key)
            if value is None:
                value = self._step_values[key] = self.atoms[lit.index](self.states[v], self.states[w])
            if value == lit.negated:
                return False
        return True

    def succ(self, i: int) -> Iterable[int]:
        return self.rows[i]


class BehaviourChecker(LivenessChecker):
    """`LivenessChecker` on the behaviour graph: fairness is a property of the states
    (ENABLED is evaluated once per state), and a node stays forever only on a self-loop."""

    def __init__(self, bg: BehaviourGraph, fairness: list[Fairness], check_memory: Callable[[], None]) -> None:
        super().__init__(bg, [bg.states[v] for v in bg.state_of], bg.initial, fairness, check_memory)  # type: ignore[arg-type]
        self.bg = bg
        self._state_enabled = [bytearray(len(bg.states)) for _ in fairness]
        # Is a step an <<A>>_v step, per fairness conjunct and pair of states: the same step
        # recurs in many nodes (one per particle) and in every sub-component tried.
        self._state_taken: list[dict[int, bool]] = [{} for _ in fairness]

    def has_self_loop(self, v: int) -> bool:
        return bool(self.bg.self_loop[v])

    def enabled(self, fi: int, v: int) -> bool:
        c, s = self._state_enabled[fi], self.bg.state_of[v]
        if not c[s]:
            c[s] = 2 if self.fairness[fi].enabled(self.bg.states[s]) else 1
        return c[s] == 2

    def taken_in(self, fi: int, comp: list[int], inside: set[int]) -> tuple[int, int] | None:
        cache, taken = self._state_taken[fi], self.fairness[fi].taken
        of, states, n = self.bg.state_of, self.bg.states, len(self.bg.states)
        for u in comp:
            su = of[u]
            for w in self.tail_succ(u):
                if w in inside:
                    key = su * n + of[w]
                    t = cache.get(key)
                    if t is None:
                        t = cache[key] = bool(taken(states[su], states[of[w]]))
                    if t:
                        return u, w
        return None

    def counterexample_lasso(self) -> Lasso | None:
        """The shortest (in states) fair, fulfilling lasso of the behaviour graph, in states."""
        bg, tab = self.bg, self.bg.tableau
        n = bg.n
        self.k = 1  # one phase: _path_to walks the BFS parents of the nodes themselves
        visits = [bytearray((tab.particles[bg.particle_of[i]].fulfils >> p) & 1 for i in range(n))
                  for p in range(len(tab.promises))]
        comps = strongly_connected(range(n), bg.succ, lambda _: True, n)
        self.check_memory()
        best: Lasso | None = None
        for comp in comps:
            found = self._fair_part(comp, visits)
            if found is None:
                continue
            part, needs = found
            entry = min(part, key=lambda i: bg.dist[i])
            if best is not None and bg.dist[entry] + 1 >= len(best.nodes):
                continue  # its lasso cannot be shorter
            cycle = self._cycle(entry, part, needs)
            prefix = self._path_to(entry, bg.parent)
            lasso = self._project(prefix, cycle)
            if best is None or len(lasso.nodes) < len(best.nodes):
                best = lasso
        return best

    def _project(self, prefix: list[int], cycle: list[int]) -> Lasso:
        """The lasso of behaviour-graph nodes `prefix`, then `cycle` and back to the
        last node of the prefix, as states (stuttering steps merged)."""
        of = self.bg.state_of
        states: list[int] = []
        for i in prefix:
            if not states or states[-1] != of[i]:
                states.append(of[i])
        loop = len(states) - 1
        while loop > 0 and states[loop - 1] == states[-1]:
            loop -= 1
        ring = [of[i] for i in cycle]
        for s in ring:
            if states[-1] != s:
                states.append(s)
        while len(states) - 1 > loop and states[-1] == states[loop]:
            states.pop()  # the cycle ends by stuttering back into its first state
        return Lasso(states, loop, len(states) - 1 == loop)


def tableau_counterexample(graph: StateGraph, states: list[tuple], initial: list[int], fairness: list[Fairness],
                           ob: Obligation, check_memory: Callable[[], None]) -> Lasso | None:
    assert ob.formula is not None
    try:
        tab = tableau.build(ltl.negate(ob.formula))
    except OverflowError as e:
        raise UnsupportedError(f"property {ob.name}: {e}; a formula this large is not supported", ob.p.loc) from None
    bg = BehaviourGraph(graph, states, initial, tab, ob.atoms, check_memory)
    check_memory()
    return BehaviourChecker(bg, fairness, check_memory).counterexample_lasso()


def violated_on_lasso(ob: Obligation, states: list[tuple], loop: int) -> bool:
    """Does the lasso (states, then back to states[loop]; a stuttering lasso loops on
    its last state) violate the general property?"""
    assert ob.formula is not None
    # A step predicate is evaluated on the step to the next state (the last state's
    # next is states[loop]); a state predicate ignores the second state.
    following = states[1:] + [states[loop]]
    values = [[bool(a(s, t)) for a in ob.atoms] for s, t in zip(states, following)]
    return not ltl.holds_on_lasso(ob.formula, values, loop)
