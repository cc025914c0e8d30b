"""Strongly connected components of a subgraph, by Tarjan's algorithm with an
explicit stack (no recursion: behaviour graphs have millions of nodes)."""

from __future__ import annotations

from array import array
from typing import Callable, Iterable


def strongly_connected(nodes: Iterable[int], succ: Callable[[int], Iterable[int]],
                       member: Callable[[int], bool]) -> list[list[int]]:
    """The SCCs of the subgraph induced by `nodes` (`member(v)` tells whether v is one
    of them), in Tarjan's order (a component before the components that reach it)."""
    index: dict[int, int] = {}
    low: dict[int, int] = {}
    on_stack: set[int] = set()
    stack = array("q")
    out: list[list[int]] = []
    counter = 0
    for root in nodes:
        if root in index:
            continue
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        work = [(root, iter(succ(root)))]
        while work:
            v, it = work[-1]
            pushed = False
            for w in it:
                if not member(w):
                    continue
                if w not in index:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(succ(w))))
                    pushed = True
                    break
                if w in on_stack and index[w] < low[v]:
                    low[v] = index[w]
            if pushed:
                continue
            work.pop()
            if work:
                u = work[-1][0]
                if low[v] < low[u]:
                    low[u] = low[v]
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                out.append(comp)
    return out
