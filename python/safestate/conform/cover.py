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


def _components(g: Graph, out: list[list[int]]) -> list[int]:
    """Strongly connected component of each node (iterative Tarjan)."""
    index = [-1] * g.n
    low = [0] * g.n
    comp = [-1] * g.n
    on_stack = bytearray(g.n)
    stack: list[int] = []
    counter = 0
    ncomp = 0
    for root in range(g.n):
        if index[root] != -1:
            continue
        work = [(root, 0)]
        while work:
            u, i = work.pop()
            if i == 0:
                index[u] = low[u] = counter
                counter += 1
                stack.append(u)
                on_stack[u] = 1
            edges = out[u]
            while i < len(edges):
                v = g.dst[edges[i]]
                i += 1
                if index[v] == -1:
                    work.append((u, i))
                    work.append((v, 0))
                    break
                if on_stack[v]:
                    low[u] = min(low[u], index[v])
            else:
                if low[u] == index[u]:
                    while True:
                        v = stack.pop()
                        on_stack[v] = 0
                        comp[v] = ncomp
                        if v == u:
                            break
                    ncomp += 1
                if work:
                    p = work[-1][0]
                    low[p] = min(low[p], low[u])
    return comp


class _Walker:
    """The untaken edges: a flag per edge and a count per node."""

    def __init__(self, g: Graph, out: list[list[int]]) -> None:
        self.g = g
        self.out = out
        self.taken = bytearray(len(g.src))
        self.left = [len(o) for o in out]
        self.pos = [0] * g.n
        self.comp = _components(g, out)

    def take(self, e: int) -> None:
        if not self.taken[e]:
            self.taken[e] = 1
            self.left[self.g.src[e]] -= 1

    def choose(self, u: int) -> int:
        """An untaken out-edge of u, or -1.  Preferred, in this order: one that stays
        in u's strongly connected component (leaving it is for good, so it is kept
        for last) and whose target keeps an untaken out-edge; one that stays; one
        whose target keeps an untaken out-edge; the first."""
        if not self.left[u]:
            return -1
        edges, taken, left, dst, comp = self.out[u], self.taken, self.left, self.g.dst, self.comp
        i = self.pos[u]
        while taken[edges[i]]:
            i += 1
        self.pos[u] = i
        here = comp[u]
        best = -1
        best_rank = 4
        for j in range(i, len(edges)):
            e = edges[j]
            if taken[e]:
                continue
            v = dst[e]
            rank = (0 if comp[v] == here else 2) + (0 if left[v] > (1 if v == u else 0) else 1)
            if rank < best_rank:
                best, best_rank = e, rank
                if rank == 0:
                    break
        return best

    def detour(self, start: int, limit: int) -> list[int] | None:
        """Shortest path from `start` to a node with an untaken out-edge, searching
        at most `limit` nodes."""
        out, dst, src, left = self.out, self.g.dst, self.g.src, self.left
        prev: dict[int, int] = {start: -1}
        queue: deque[int] = deque([start])
        while queue and len(prev) <= limit:
            u = queue.popleft()
            for e in out[u]:
                v = dst[e]
                if v in prev:
                    continue
                prev[v] = e
                if left[v]:
                    path: list[int] = []
                    while v != start:
                        path.append(prev[v])
                        v = src[prev[v]]
                    path.reverse()
                    return path
                queue.append(v)
        return None


def cover(g: Graph, max_len: int = 1000, detour_nodes: int = 256) -> list[Trace]:
    """Traces from initial nodes that take every edge at least once (deterministic)."""
    if max_len < 1:
        raise ValueError("max_len must be at least 1")
    out = g.out_edges()
    parent, order = bfs_tree(g, out)
    w = _Walker(g, out)
    traces: list[Trace] = []
    k = 0  # position in BFS order of the next node that may have untaken edges
    while True:
        while k < len(order) and not w.left[order[k]]:
            k += 1
        if k == len(order):
            return traces
        node = order[k]
        start, path = tree_path(g, parent, node)
        for e in path:
            w.take(e)
        fresh = 0  # untaken edges taken by this trace: at least one, so the loop ends
        while True:
            e = w.choose(node)
            if e == -1:
                d = w.detour(node, detour_nodes)
                if d is None or len(path) + len(d) >= max_len:
                    break
                for x in d:
                    w.take(x)
                path.extend(d)
                node = g.dst[d[-1]]
                continue
            if len(path) >= max_len and fresh:
                break
            fresh += 1
            w.take(e)
            path.append(e)
            node = g.dst[e]
        traces.append(Trace(start, path))


def steps(traces: list[Trace]) -> int:
    return sum(len(t.edges) for t in traces)
