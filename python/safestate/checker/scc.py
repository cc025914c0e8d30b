"""Strongly connected components of a subgraph, by Tarjan's algorithm with an
explicit stack (no recursion: behaviour graphs have millions of nodes)."""

from __future__ import annotations

from array import array
from typing import Callable, Iterable


def strongly_connected(nodes: Iterable[int], succ: Callable[[int], Iterable[int]],
                       member: Callable[[int], object], n: int) -> list[list[int]]:
    """The SCCs of the subgraph induced by `nodes` (ids below `n`; `member(v)` tells
    whether v is one of them), in Tarjan's order (a component before the components
    that reach it)."""
    index = array("q", [-1]) * n
    low = array("q", [0]) * n
    on_stack = bytearray(n)
    stack = array("q")
    out: list[list[int]] = []
    counter = 0
    for root in nodes:
        if index[root] >= 0:
            continue
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack[root] = 1
        work = [(root, iter(succ(root)))]
        while work:
            v, it = work[-1]
            pushed = False
            for w in it:
                if not member(w):
                    continue
                if index[w] < 0:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack[w] = 1
                    work.append((w, iter(succ(w))))
                    pushed = True
                    break
                if on_stack[w] and index[w] < low[v]:
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
                    on_stack[w] = 0
                    comp.append(w)
                    if w == v:
                        break
                out.append(comp)
    return out
