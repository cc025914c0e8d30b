"""Concrete traces: the cover's edge sequences turned into model states.

A graph node stands for every state with the same VIEW; the concrete state reached
along a path can differ from the node's representative in what the VIEW leaves out
(e.g. last_reject_reason), and the C++ must match the concrete one.  So each step's
state is the model successor of the previous concrete state under the edge's event
(`ModelStepper.successor`), and its VIEW is checked to be the edge's target node.
Without a VIEW the node is the concrete state, and the checker's edge is used as it is.

Every trace starts with the BFS-tree path to a node; the concrete states along
tree paths are the same for every trace, so they are computed once per node.
"""

from __future__ import annotations

from dataclasses import dataclass

from .cover import Trace
from .events import Event
from .graph import StateGraph
from .model_step import ModelStepper


@dataclass
class Step:
    event: Event
    state: tuple
    edge: int  # the graph edge this step takes (-1 when replaying a file)


@dataclass
class ConcreteTrace:
    initial: tuple
    steps: list[Step]


class GraphMismatch(Exception):
    """A step's successor is not in the node its edge points to (VIEW unsound?)."""


class Materializer:
    def __init__(self, stepper: ModelStepper, graph: StateGraph) -> None:
        self.stepper = stepper
        self.g = graph
        self.parent = [-1] * len(graph.states)
        self.tree: dict[int, tuple] = {}  # node -> concrete state at the end of its tree path
        self._keys: dict[int, object] = {}
        # (id of a concrete state, edge) -> its successor: traces share off-tree steps too
        # (each entry keeps its source state alive, so an id is never reused).
        self._off_tree: dict[tuple[int, int], tuple[tuple, tuple]] = {}
        # The checker found each edge's successor; only a VIEW can make it differ from the node.
        self.no_view = stepper.model.view is None

    def set_tree(self, parent: list[int]) -> None:
        self.parent = parent

    def _check(self, state: tuple, node: int) -> None:
        key = self.stepper.key
        want = self._keys.get(node)
        if want is None:
            want = self._keys[node] = key(self.g.states[node])
        if key(state) != want:
            raise GraphMismatch(f"the successor is not the graph's node {node}")

    def trace(self, t: Trace) -> ConcreteTrace:
        g = self.g
        cur = g.states[t.start]  # an initial state: the representative is the state itself
        steps: list[Step] = []
        on_tree = True
        for e in t.edges:
            ev, dst = g.events[e], g.dst[e]
            on_tree = on_tree and self.parent[dst] == e
            nxt = self.tree.get(dst) if on_tree else None
            if nxt is None and self.no_view:
                nxt = g.states[dst]  # without a VIEW the node is the concrete state itself
            if nxt is None:
                hit = self._off_tree.get((id(cur), e))
                if hit is not None and hit[0] is cur:
                    nxt = hit[1]
                else:
                    nxt = self.stepper.edge_successor(cur, ev)
                    self._check(nxt, dst)
                    self._off_tree[(id(cur), e)] = (cur, nxt)
                if on_tree:
                    self.tree[dst] = nxt
            steps.append(Step(ev, nxt, e))
            cur = nxt
        return ConcreteTrace(g.states[t.start], steps)
