"""Liveness checking on the explored state graph, under weak and strong fairness.

Each liveness conjunct is checked through its negation, which for the supported
forms is "eventually the behaviour enters a *tail* that it never leaves":

=============  ==========================  =====================  ==================
property       the tail starts at a state  every tail state       infinitely often
=============  ==========================  =====================  ==================
``<>P``        initial, with ~P            satisfies ~P           -
``P ~> Q``     with P /\\ ~Q               satisfies ~Q           -
``[]<>P``      with ~P                     satisfies ~P           -
``<>[]P``      any                         any                    a state with ~P
``[]<><<A>>_v``  any                       no <<A>>_v step        -
``WF_v(A)``    with ENABLED <<A>>_v        ENABLED <<A>>_v,       -
                                           no <<A>>_v step
``SF_v(A)``    any                         no <<A>>_v step        ENABLED <<A>>_v
``[](P =>``    with ~Q, after a state      any                    -
``[]Q)``       with P (an extra phase)
``P => []Q``   with ~Q, after an initial   any                    -
               state with P (extra phase)
``P => <>Q``   initial, with P /\\ ~Q      satisfies ~Q           -
=============  ==========================  =====================  ==================

The behaviour graph is the product of the state graph with this two-phase
automaton (phase 0: before the tail, phase 1: in it; ``[](P => []Q)`` has three:
before P, after P, and the tail from a ~Q state on).  As TLC does, every state
has a stuttering self-loop, so a behaviour may end by stuttering.  A counterexample
is a strongly connected component (iterative Tarjan, `scc.py`) of phase 1 that is
*fair*: every WF action that is enabled in all its states is taken in it, and
every SF action that is enabled in one of its states is taken in it (states where
an untaken SF action is enabled are removed and the rest split again, as in
Emerson-Lei's algorithm).  "Taken" means an ``<<A>>_v`` step between two states of
the component.

The counterexample is a lasso: the shortest prefix to a fair component (0-1 BFS
over the product), then a cycle inside it through the steps and states fairness
needs (or stuttering in one state when it needs none); among the fair components
the one giving the fewest states is taken.
"""

from __future__ import annotations

from array import array
from collections import deque
from dataclasses import dataclass
from typing import Callable, Iterable

from ..tla.errors import TlaError
from . import ltl
from .scc import strongly_connected
from .temporal import Fairness, Obligation


@dataclass
class Lasso:
    """A behaviour: `nodes` in order, then back to ``nodes[loop]`` (or stuttering in
    the last state when `stuttering`)."""

    nodes: list[int]
    loop: int
    stuttering: bool


class StateGraph:
    """The explored graph in compressed rows: successors of v are
    ``targets[offsets[v]:offsets[v + 1]]`` (distinct, self-loops dropped: every
    state stutters anyway)."""

    def __init__(self, n: int, src: array, dst: array) -> None:
        self.n = n
        self.offsets = array("q", [0]) * (n + 1)
        self.targets = array("i")
        # The search expands states in order, so the steps come grouped by source.
        i, m = 0, len(src)
        for v in range(n):
            row: set[int] = set()
            while i < m and src[i] == v:
                w = dst[i]
                i += 1
                if w != v and w not in row:
                    row.add(w)
                    self.targets.append(w)
            self.offsets[v + 1] = len(self.targets)
        if i != m:
            raise TlaError("internal", "liveness: the steps of the state graph are not grouped by source")

    def succ(self, v: int) -> Iterable[int]:
        return self.targets[self.offsets[v]:self.offsets[v + 1]]


class LivenessChecker:
    def __init__(self, graph: StateGraph, states: list[tuple], initial: list[int],
                 fairness: list[Fairness], check_memory: Callable[[], None]) -> None:
        self.check_memory = check_memory
        self.g = graph
        self.states = states
        self.initial = initial
        self.fairness = fairness
        # ENABLED cache per fairness conjunct: 0 unknown, 1 disabled, 2 enabled.
        self._enabled = [bytearray(graph.n) for _ in fairness]
        # The steps a tail may take: all, or those of the current property's `forbid`.
        self._forbid: Callable[[tuple, tuple], bool] | None = None
        self._rows: dict[int, list[int]] = {}
        self.k = 2  # phases of the property's automaton (see `counterexample`)

    def tail_succ(self, v: int) -> Iterable[int]:
        """Successors of v by steps a tail may take (stuttering is always allowed)."""
        forbid = self._forbid
        if forbid is None:
            return self.g.succ(v)
        row = self._rows.get(v)
        if row is None:
            s = self.states[v]
            row = self._rows[v] = [w for w in self.g.succ(v) if not forbid(s, self.states[w])]
        return row

    def enabled(self, fi: int, v: int) -> bool:
        c = self._enabled[fi]
        if not c[v]:
            c[v] = 2 if self.fairness[fi].enabled(self.states[v]) else 1
        return c[v] == 2

    def taken_in(self, fi: int, comp: list[int], inside: set[int]) -> tuple[int, int] | None:
        """A step of the component that is an <<A>>_v step of fairness conjunct fi."""
        taken = self.fairness[fi].taken
        for u in comp:
            for w in self.tail_succ(u):
                if w in inside and taken(self.states[u], self.states[w]):
                    return u, w
        return None

    # ------------------------------------------------------------------ search
    def counterexample(self, ob: Obligation) -> Lasso | None:
        n = self.g.n
        self._forbid = ob.forbid
        self._rows = {}
        self.k = 3 if ob.kind in ("stays", "init_always") else 2  # automaton phases; the last is the tail
        k = self.k
        stay, start, visit = self._masks(ob)
        dist, parent = self._product_bfs(ob, stay, start)
        self.check_memory()
        tail = [v for v in sorted(range(n), key=lambda v: dist[k * v + k - 1]) if dist[k * v + k - 1] >= 0]
        in_tail = bytearray(n)
        for v in tail:
            in_tail[v] = 1
        best: tuple[int, int, list[int]] | None = None
        comps = strongly_connected(tail, self.tail_succ, in_tail.__getitem__, n)
        self.check_memory()
        for comp in comps:
            found = self._fair_part(comp, [] if visit is None else [visit])
            if found is None:
                continue
            part, needs = found
            entry = min(part, key=lambda v: dist[k * v + k - 1])
            if best is not None and dist[k * entry + k - 1] >= best[0]:
                continue  # its lasso cannot be shorter
            cycle = self._cycle(entry, part, needs)
            length = dist[k * entry + k - 1] + len(cycle)
            if best is None or length < best[0]:
                best = (length, entry, cycle)
        if best is None:
            return None
        _, entry, cycle = best
        prefix = self._path_to(k * entry + k - 1, parent)
        if not cycle:
            return Lasso(prefix, len(prefix) - 1, True)
        return Lasso(prefix + cycle, len(prefix) - 1, False)

    def _masks(self, ob: Obligation) -> tuple[bytearray, bytearray, bytearray | None]:
        n = self.g.n
        stay = bytearray(n)
        start = bytearray(n)
        visit = None
        p, q, states = ob.p, ob.q, self.states
        for v in range(n):
            s = states[v]
            if ob.kind in ("stable", "sf", "infinitely_step"):
                stay[v] = start[v] = 1
            elif ob.kind in ("stays", "init_always"):
                assert q is not None
                stay[v] = 1
                start[v] = not q(s)
            elif ob.kind == "init_eventually":
                assert q is not None
                stay[v] = not q(s)
                start[v] = stay[v] and p(s)
            elif ob.kind == "wf":
                stay[v] = start[v] = p(s)
            elif ob.kind == "leadsto":
                assert q is not None
                stay[v] = not q(s)
                start[v] = stay[v] and p(s)
            else:
                stay[v] = start[v] = not p(s)
        if ob.kind == "stable":
            visit = bytearray(not p(states[v]) for v in range(n))
        elif ob.kind == "sf":
            visit = bytearray(p(states[v]) for v in range(n))
        return stay, start, visit

    def _product_bfs(self, ob: Obligation, stay: bytearray, start: bytearray) -> tuple[array, array]:
        """0-1 BFS over (state, phase) nodes k*v+phase; entering the next phase costs
        nothing.  With three phases (``[](P => []Q)``) phase 1 is entered at a P state
        and the tail (phase 2) at a ~Q state."""
        n, k = self.g.n, self.k
        last = k - 1
        p = ob.p
        states = self.states
        dist = array("q", [-1]) * (k * n)
        parent = array("q", [-1]) * (k * n)
        dq: deque[int] = deque()
        for v in self.initial:
            if ob.kind == "init_always" and not p(states[v]):
                continue  # P => []Q holds on behaviours from here
            if ob.kind in ("eventually", "init_eventually") and not start[v]:
                continue
            node = k * v + (last if ob.kind in ("eventually", "init_eventually") else
                            1 if ob.kind == "init_always" else 0)
            if dist[node] < 0:
                dist[node] = 0
                dq.append(node)
        done = bytearray(k * n)
        while dq:
            node = dq.popleft()
            if done[node]:
                continue
            done[node] = 1
            v, phase = divmod(node, k)
            if phase < last:
                step = start[v] if phase == k - 2 else p(states[v])  # k - 2: the phase before the tail
                if step and (dist[node + 1] < 0 or dist[node + 1] > dist[node]):
                    dist[node + 1] = dist[node]
                    parent[node + 1] = node
                    dq.appendleft(node + 1)
            for w in (self.tail_succ(v) if phase == last else self.g.succ(v)):
                if phase == last and not stay[w]:
                    continue
                nxt = k * w + phase
                if dist[nxt] < 0 or dist[nxt] > dist[node] + 1:
                    dist[nxt] = dist[node] + 1
                    parent[nxt] = node
                    dq.append(nxt)
        return dist, parent

    def _path_to(self, node: int, parent: array) -> list[int]:
        path: list[int] = []
        while node >= 0:
            v = node // self.k
            if not path or path[-1] != v:
                path.append(v)
            node = parent[node]
        path.reverse()
        return path

    def has_self_loop(self, v: int) -> bool:
        """Can the behaviour stay in v forever?  In the state graph every state stutters."""
        return True

    def _fair_part(self, comp: list[int], visits: list[bytearray]) -> tuple[list[int], list] | None:
        """A fair sub-component of `comp` that visits a state of each of `visits`, with
        the steps and states a fair cycle in it must pass through; None if there is none."""
        work = [comp]
        while work:
            part = work.pop()
            if len(part) == 1 and not self.has_self_loop(part[0]):
                continue  # no cycle
            inside = set(part)
            taken = [self.taken_in(fi, part, inside) for fi in range(len(self.fairness))]
            bad = {v for fi, f in enumerate(self.fairness) if f.kind == "SF" and taken[fi] is None
                   for v in part if self.enabled(fi, v)}
            if bad:
                rest = [v for v in part if v not in bad]
                keep = set(rest)
                work.extend(strongly_connected(rest, self.tail_succ, keep.__contains__, self.g.n))
                continue
            needs: list = []
            fair = True
            for fi, f in enumerate(self.fairness):
                if f.kind == "WF":
                    # Met by a step taking A or a state where A is disabled.  Taking A is
                    # checked first: it is cheaper than ENABLED.
                    if taken[fi] is None and all(self.enabled(fi, v) for v in part):
                        fair = False
                        break
                    needs.append(("wf", fi))
                elif taken[fi] is not None and any(self.enabled(fi, v) for v in part):
                    needs.append(("step", fi))
            if not fair:
                continue
            for visit in visits:
                targets = {v for v in part if visit[v]}
                if not targets:
                    fair = False
                    break
                needs.append(("state", targets))
            if fair:
                return part, needs
        return None

    def _cycle(self, entry: int, part: list[int], needs: list) -> list[int]:
        """States after `entry` on a cycle through `needs` inside `part`, ending just
        before `entry` again; [] when stuttering in `entry` meets every need.  Greedy:
        go to the nearest place that meets a need (the most needs among equals)."""
        inside = set(part)
        open_needs = [nd for nd in needs if not self._meets(nd, None, entry)]
        cycle: list[int] = []
        cur = entry
        while open_needs:
            path = self._nearest(cur, inside, open_needs)
            for w in path:
                open_needs = [nd for nd in open_needs if not self._meets(nd, cur, w)]
                cur = w
            cycle.extend(path)
        if not cycle:
            if self.has_self_loop(entry):
                return []
            cycle = self._bfs_path(entry, {entry}, inside, leave=True)  # the shortest way round
        full = cycle + self._bfs_path(cur, {entry}, inside)
        return full[:-1]  # it ends with `entry`, where the lasso loops back to

    def _meets(self, need: tuple, u: int | None, w: int) -> bool:
        """Does arriving in state w (by the step u -> w, unless u is None) meet `need`?"""
        kind, what = need
        if kind == "state":
            return w in what
        if kind == "wf" and not self.enabled(what, w):
            return True
        return u is not None and self.fairness[what].taken(self.states[u], self.states[w])

    def _nearest(self, src: int, inside: set[int], needs: list) -> list[int]:
        """The shortest path from src (without it) whose last state or step meets a
        need; among the shortest, one that meets the most."""
        prev = {src: -1}
        level = [src]
        while level:
            best: tuple[int, int] | None = None
            best_score = 0
            nxt: list[int] = []
            for v in level:
                for w in self.tail_succ(v):
                    if w not in inside:
                        continue
                    score = sum(1 for nd in needs if self._meets(nd, v, w))
                    if score > best_score:
                        best, best_score = (v, w), score
                    if w not in prev:
                        prev[w] = v
                        nxt.append(w)
            if best is not None:
                return _path_back(prev, src, *best)
            level = nxt
        raise TlaError("internal", "liveness: a need of a fair component is unreachable inside it")

    def _bfs_path(self, src: int, goals: set[int], inside: set[int], leave: bool = False) -> list[int]:
        """Shortest path inside the component from src to a state of `goals`, without src
        (with at least one step when `leave`)."""
        if src in goals and not leave:
            return []
        prev = {src: -1}
        dq = deque([src])
        while dq:
            v = dq.popleft()
            for w in self.tail_succ(v):
                if w not in inside:
                    continue
                if w in goals:
                    return _path_back(prev, src, v, w)
                if w not in prev:
                    prev[w] = v
                    dq.append(w)
        raise TlaError("internal", "liveness: no path inside a strongly connected component")


# Properties whose negation TLC checks with a tableau (it is not of the forms
# []<>A / <>[]A).  TLC's Liveness.processLiveness gathers them in the orders of
# solution it checks before the ones without a tableau; within one, the search finds
# the counterexample nearest the initial states first (e.g. stuttering there).
TABLEAU_KINDS = ("eventually", "leadsto", "stays", "init_always", "init_eventually", "tableau")


def find_violation(graph: StateGraph, states: list[tuple], initial: list[int], fairness: list[Fairness],
                   obligations: list[Obligation],
                   check_memory: Callable[[], None]) -> tuple[Obligation, Lasso] | None:
    """A liveness obligation with a fair counterexample, chosen as TLC does: its
    groups (`tlc_check_order`) in order, the first with a violation; in it the
    shortest counterexample (the first in .cfg order among equals)."""
    from .tableau_search import tableau_counterexample  # it builds on LivenessChecker
    checker = LivenessChecker(graph, states, initial, fairness, check_memory)
    for group in tlc_check_order(obligations):
        best: tuple[Obligation, Lasso] | None = None
        for ob in group:
            check_memory()
            lasso = (tableau_counterexample(graph, states, initial, fairness, ob, check_memory)
                     if ob.kind == "tableau" else checker.counterexample(ob))
            if lasso is not None and (best is None or len(lasso.nodes) < len(best[1].nodes)):
                best = (ob, lasso)
        if best is not None:
            return best
    return None


def tlc_check_order(obligations: list[Obligation]) -> list[list[Obligation]]:
    """TLC's `OrderOfSolution`s in the order it checks them (`Liveness.processLiveness`):
    the negated properties' DNF disjuncts in .cfg order, except that a disjunct that is
    just ``[]<>A`` goes last (`LNDisj.toDNF` merges those into one at the end), lumped
    by their tableau formula; those without one (only ``<>[]A`` / ``[]<>A`` conjuncts)
    share one group, at the place of the first.  A group's search finds the
    counterexample nearest the initial states.  An obligation is placed by the first of
    its disjuncts in that order."""
    ordered: list[tuple[Obligation, bool]] = []  # (obligation, its disjunct needs a tableau)
    last: list[tuple[Obligation, bool]] = []
    for ob in obligations:
        for needs_tableau, only_ae in _disjunct_kinds(ob):
            (last if only_ae else ordered).append((ob, needs_tableau))
    groups: list[list[Obligation]] = []
    shared: list[Obligation] | None = None
    placed: set[int] = set()
    for ob, needs_tableau in ordered + last:
        if id(ob) in placed:
            continue
        placed.add(id(ob))
        if needs_tableau:
            groups.append([ob])
            continue
        if shared is None:
            shared = []
            groups.append(shared)
        shared.append(ob)
    return groups


def _disjunct_kinds(ob: Obligation) -> list[tuple[bool, bool]]:
    """For each DNF disjunct of the obligation's negation: does it need a tableau, is
    it just ``[]<>A``?"""
    if ob.kind != "tableau":
        # <>[]P is negated to []<>~P; the other forms without a tableau are not []<>A.
        return [(ob.kind in TABLEAU_KINDS, ob.kind == "stable")]
    assert ob.formula is not None
    conjunctions = ltl.disjuncts(ltl.negate(ob.formula)) or [[ob.formula]]
    return [(not all(ltl.without_tableau(c) for c in d),
             len(d) == 1 and isinstance(d[0], ltl.Always) and ltl.without_tableau(d[0])) for d in conjunctions]


def violated_on(ob: Obligation, states: list[tuple], loop: int, stutters: bool) -> bool:
    """Does the lasso (`states`, then back to states[loop], or stuttering in the last
    state) violate the liveness obligation?  TLC names every property its
    counterexample violates."""
    if ob.kind == "tableau":
        from .tableau_search import violated_on_lasso
        return violated_on_lasso(ob, states, loop)
    cycle = states[loop:]
    steps = [] if stutters else list(zip(cycle, cycle[1:] + cycle[:1]))
    p, q = ob.p, ob.q
    forbid = ob.forbid
    if ob.kind == "eventually":
        return not any(p(s) for s in states)
    if ob.kind == "leadsto":
        assert q is not None
        later_q = any(q(s) for s in cycle)
        return not later_q and any(p(s) and not any(q(x) for x in states[i:]) for i, s in enumerate(states))
    if ob.kind == "infinitely":
        return not any(p(s) for s in cycle)
    if ob.kind == "stable":
        return not all(p(s) for s in cycle)
    if ob.kind == "stays":
        assert q is not None
        return any(p(s) and not all(q(x) for x in states[i:]) for i, s in enumerate(states))
    if ob.kind == "init_always":
        assert q is not None
        return p(states[0]) and not all(q(x) for x in states)
    if ob.kind == "init_eventually":
        assert q is not None
        return p(states[0]) and not any(q(x) for x in states)
    assert forbid is not None
    taken = any(forbid(s, t) for s, t in steps)
    if ob.kind == "infinitely_step":
        return not taken
    if ob.kind == "wf":
        return not taken and all(p(s) for s in cycle)
    return not taken and any(p(s) for s in cycle)  # sf


def _path_back(prev: dict[int, int], src: int, v: int, w: int) -> list[int]:
    """The path from src (excluded) to w, whose last step is v -> w, read back through
    the BFS's predecessor map."""
    path = [w]
    while v != src:
        path.append(v)
        v = prev[v]
    path.reverse()
    return path
