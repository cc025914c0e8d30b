"""Trace cover: a set of paths from initial nodes that together take every edge.

Works on an abstract graph (integer nodes, integer edges), so it is independent of
TLA+ and can be unit-tested on hand-made graphs.  The strategy is deterministic:

1. a BFS tree from the initial nodes gives a shortest path to any node;
2. a trace starts with the tree path to the shallowest node that still has an
   untaken out-edge, then greedily takes untaken out-edges, preferring one whose
   target still has untaken out-edges (so the walk can go on);
3. when the current node has none left, it detours along a shortest path to a
   nearby node that has one (re-taking covered edges); the search for it is
   bounded (`detour_nodes`), because past that a fresh trace from an initial node
   (at most the BFS depth) is as short;
4. a trace ends there, or when it reaches `max_len` steps.

Every edge is taken at least once: each trace takes at least one untaken edge,
and every edge's source is reachable from an initial node (else UnreachableEdges).
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass


@dataclass(frozen=True)
class Graph:
    """Nodes 0..n-1; edge i goes from src[i] to dst[i]."""

    n: int
    initial: list[int]
    src: list[int]
    dst: list[int]

    def out_edges(self) -> list[list[int]]:
        out: list[list[int]] = [[] for _ in range(self.n)]
        for i, s in enumerate(self.src):
            out[s].append(i)
        return out


@dataclass(frozen=True)
class Trace:
    start: int          # an initial node
    edges: list[int]    # edge ids, each leaving the previous edge's dst


class UnreachableEdges(Exception):
    """Some edges leave nodes that no initial node reaches: no trace can take them."""


def bfs_tree(g: Graph, out: list[list[int]] | None = None) -> tuple[list[int], list[int]]:
    """Parent edge of each node (-1 for initial / unreached) and the BFS order."""
    if out is None:
        out = g.out_edges()
    parent = [-1] * g.n
    seen = [False] * g.n
    order: list[int] = []
    queue: deque[int] = deque()
    for s in g.initial:
        if not seen[s]:
            seen[s] = True
            queue.append(s)
    while queue:
        u = queue.popleft()
        order.append(u)
        for e in out[u]:
            v = g.dst[e]
            if not seen[v]:
                seen[v] = True
                parent[v] = e
                queue.append(v)
    missing = [u for u in range(g.n) if not seen[u] and out[u]]
    if missing:
        raise UnreachableEdges(f"{len(missing)} node(s) with out-edges are not reachable, e.g. {missing[:5]}")
    return parent, order


def tree_path(g: Graph, parent: list[int], node: int) -> tuple[int, list[int]]:
    path: list[int] = []
    while parent[node] != -1:
        e = parent[node]
        path.append(e)
        node = g.src[e]
    path.reverse()
    return node, path


def cover(g: Graph, max_len: int = 1000, detour_nodes: int = 256,
          tree: tuple[list[int], list[int]] | None = None) -> list[Trace]:
    """Traces from initial nodes that take every edge at least once (deterministic).
    `tree` is `bfs_tree(g)` when the caller has it already.

    The walk of steps 2-4 above runs in the binding `safestate._cover`
    (bindings/python/cover_module.cpp): its detours visit tens of millions of edges on
    the larger graphs."""
    if max_len < 1:
        raise ValueError("max_len must be at least 1")
    from .. import _cover  # type: ignore[attr-defined]

    parent, order = tree if tree is not None else bfs_tree(g)
    starts, offsets, edges = _cover.cover(g.n, g.src, g.dst, parent, order, max_len, detour_nodes)
    return [Trace(s, edges[offsets[k]:offsets[k + 1]]) for k, s in enumerate(starts)]


def steps(traces: list[Trace]) -> int:
    return sum(len(t.edges) for t in traces)
