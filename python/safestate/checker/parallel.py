"""Multi-process expansion of large BFS levels.

Worker processes are forked after the model is compiled (so they share it) and
evaluate the next-state relation for chunks of a BFS level.  The parent merges
their successor lists in exactly the order a single worker would have produced
them, and does the counting, deduplication, constraint and invariant checks
itself; a state whose expansion failed in a worker is re-expanded in the parent
to report the error.  Hence verdicts, counts, depth and traces do not depend on
the number of workers.
"""

from __future__ import annotations

import multiprocessing
from typing import Any, Callable

from ..tla.errors import TlaError
from .explore import Explorer, Step
from .model import Model

# Levels smaller than this are expanded in the parent: forking work out costs more.
MIN_PARALLEL_LEVEL = 512
CHUNK = 256

_MODEL: Model | None = None


def _expand_chunk(states: list[tuple]) -> list[Any]:
    """Successors (state, leaf) of each state, or None where evaluation failed."""
    model = _MODEL
    assert model is not None
    out: list[Any] = []
    for st in states:
        succ: list[tuple[tuple, int]] = []
        try:
            model.run_next(st, lambda s, leaf, L: succ.append((s, leaf)))
        except (TlaError, RecursionError):
            out.append(None)
            continue
        out.append(succ)
    return out


class ParallelExplorer(Explorer):
    def __init__(self, model: Model, graph: bool, max_memory_mb: int | None,
                 progress: Callable[[str], None] | None, workers: int) -> None:
        super().__init__(model, graph, max_memory_mb, progress)
        self.workers = workers

    def _expand_all(self) -> None:
        global _MODEL
        _MODEL = self.m
        ctx = multiprocessing.get_context("fork")
        with ctx.Pool(self.workers) as pool:
            while self.head < len(self.states):
                level_end = len(self.states)
                if level_end - self.head < MIN_PARALLEL_LEVEL:
                    while self.head < level_end:
                        self.expand(self.head)
                        self.head += 1
                    continue
                chunks = [self.states[i:min(i + CHUNK, level_end)] for i in range(self.head, level_end, CHUNK)]
                for chunk_result in pool.imap(_expand_chunk, chunks):
                    for succ in chunk_result:
                        if succ is None:
                            self.expand(self.head)  # reproduces the error with exact counts
                        else:
                            self.merge(self.head, succ)
                        self.head += 1

    def merge(self, i: int, successors: list[tuple[tuple, int]]) -> None:
        """Account for the successors of state `i` as `Explorer.expand` would."""
        m = self.m
        cur = self.states[i]
        next_level = self.level[i] + 1
        constrained = bool(m.constraints or m.action_constraints)
        keyed = m.view is not None or m.symmetry is not None
        seen_get = self.seen.get
        for st, leaf in successors:
            self.generated += 1
            m.check_complete(st, leaf)
            in_model = True
            if constrained:
                in_model = m.in_model(st) and m.action_ok(cur, st)
            new = True
            idx = -1
            if in_model:
                key = m.key(st) if keyed else st
                idx = seen_get(key, -1)
                if idx < 0:
                    idx = self._add(st, key, i, leaf, next_level)
                else:
                    new = False
            if self.live_edges and in_model:
                self.edge_src.append(i)
                self.edge_dst.append(idx)
            if new:
                for inv in m.invariants:
                    if not m.holds(inv, st):
                        if idx >= 0:
                            self._finish("safety failure", inv.name, idx)
                        # A constraint-violating successor (not stored): recover its action parameters.
                        params = self._step_params(cur, leaf, st)
                        self._finish("safety failure", inv.name, i, Step(st, m.leaves[leaf].name, params))
            if m.action_properties:
                self._check_action_properties(i, cur, st, idx if new else -1, leaf,
                                              lambda: self._step_params(cur, leaf, st))
        if not successors and m.check_deadlock:
            self._finish("deadlock failure", None, i)
