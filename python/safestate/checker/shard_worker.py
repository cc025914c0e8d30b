"""One worker of the sharded breadth-first search (`parallel.py`).

Worker ``me`` of ``n`` owns the states whose key (the state, or its VIEW/SYMMETRY
reduction) hashes to ``me`` modulo ``n``: it keeps their seen-set, stores them and
expands them.  A BFS level runs in three phases, each ended by a barrier at the
coordinator (messages over a pipe):

1. **expand** its states of the level in their global BFS order; every successor
   gets the sort key (parent's position in the level, successor's rank among the
   parent's successors) — its place in a single worker's generation order.  Owned
   successors become candidates, the others are batched per owner (one candidate
   per state and level, the one with the smallest sort key) and written to a file;
2. **merge** the batches sent to it: a candidate not seen before is new; of the
   candidates for the same state the smallest sort key wins, so the parent and
   action recorded are the ones a single worker records;
3. **number** its new states: their position in the next level is their rank among
   every worker's new sort keys (the sorted key arrays are exchanged as files).

Anything a single worker would stop at (a violated invariant or action property,
a deadlock, an evaluation error) is only flagged: the coordinator then replays the
level sequentially (`parallel.py`), so counts and traces are those of one worker.
"""

from __future__ import annotations

import os
import pickle
from array import array
from bisect import bisect_left, bisect_right
from multiprocessing.connection import Connection
from typing import Any

from ..tla.enum_watch import rss_mb
from ..tla.env import UNSET
from .model import Model

RANK_BITS = 32  # a sort key packs (position in level, rank) into one signed 64-bit int
MEMORY_CHECK_EVERY = 20000


def pss_mb() -> float:
    """This process's proportional memory in MB: pages shared with the other workers
    (the model, forked from the coordinator) count once over all of them."""
    try:
        with open("/proc/self/smaps_rollup") as f:
            for line in f:
                if line.startswith("Pss:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return rss_mb()


class _Flag(Exception):
    """Ends the expansion: something a single worker stops at; the level is replayed."""


class ShardWorker:
    def __init__(self, model: Model, me: int, n: int, folder: str, conn: Connection,
                 max_memory_mb: float) -> None:
        self.m = model
        self.me = me
        self.n = n
        self.folder = folder
        self.conn = conn
        # The shards split the states evenly, so each worker gets an even share of the limit.
        self.memory_share_mb = max_memory_mb / n
        self.seen: set = set()
        self.states: list[tuple] = []
        self.level = array("i")
        self.pos = array("q")      # position in its level's global BFS order
        self.ppos = array("q")     # the parent's position in the previous level
        self.leaf = array("i")
        self.frontier: list[int] = []  # local indices of the level being expanded, in BFS order
        self.depth = 1
        self.memory_exceeded = False

    # ---------------------------------------------------------------- helpers
    def owner(self, key: Any) -> int:
        return hash(key) % self.n

    def _path(self, kind: str, src: int, dst: int = 0, depth: int | None = None) -> str:
        return os.path.join(self.folder, f"{kind}{self.depth if depth is None else depth}_{src}_{dst}")

    def _store(self, st: tuple, level: int, pos: int, ppos: int, leaf: int) -> int:
        idx = len(self.states)
        self.states.append(st)
        self.level.append(level)
        self.pos.append(pos)
        self.ppos.append(ppos)
        self.leaf.append(leaf)
        if idx % MEMORY_CHECK_EVERY == MEMORY_CHECK_EVERY - 1 and pss_mb() > self.memory_share_mb:
            self.memory_exceeded = True
            raise _Flag()
        return idx

    def _barrier(self, flagged: bool, count: int) -> str:
        """Report this phase, wait for the coordinator's decision."""
        self.conn.send((flagged, self.memory_exceeded, count))
        return self.conn.recv()

    # ---------------------------------------------------------------- the search
    def run(self, initial: list[tuple]) -> None:
        m = self.m
        keyed = m.view is not None or m.symmetry is not None
        for p, st in enumerate(initial):
            key = m.key(st) if keyed else st
            if self.owner(key) == self.me:
                self.seen.add(key)
                self.frontier.append(self._store(st, 1, p, -1, -1))
        while True:
            candidates: dict[Any, tuple] = {}
            flagged, generated = self._expand(candidates)
            decision = self._barrier(flagged, generated)
            if self.depth > 1:  # every worker has read the previous level's key files
                os.unlink(self._path("K", self.me, 0, self.depth - 1))
            if decision != "merge":
                return self._stop(decision)
            flagged, new, sort_keys = self._merge(candidates)
            decision = self._barrier(flagged, len(new))
            if decision != "number":
                return self._stop(decision)
            self._number(new, sort_keys)

    def _expand(self, candidates: dict) -> tuple[bool, int]:
        """Phase 1.  Returns (flagged, states generated)."""
        m, me, n = self.m, self.me, self.n
        seen = self.seen
        keyed = m.view is not None or m.symmetry is not None
        constrained = bool(m.constraints or m.action_constraints)
        invariants, action_properties, holds = m.invariants, m.action_properties, m.holds
        outgoing: list[dict] = [{} for _ in range(n)]
        generated = 0
        cur: tuple = ()
        p = rank = 0

        def on_succ(st: tuple, leaf: int, L: list) -> None:
            nonlocal rank
            r = rank
            rank = r + 1
            if UNSET in st:
                raise _Flag()  # not completely specified: the replay reports it
            if action_properties:
                for prop in action_properties:
                    if not holds(prop, cur, st):
                        raise _Flag()
            if constrained and not (m.in_model(st) and m.action_ok(cur, st)):
                for inv in invariants:  # TLC checks constraint-violating successors too
                    if not holds(inv, st):
                        raise _Flag()
                return
            key = m.key(st) if keyed else st
            dest = hash(key) % n
            if dest == me:
                if key not in seen and key not in candidates:
                    candidates[key] = (st, p, r, leaf)
            else:
                batch = outgoing[dest]
                if key not in batch:
                    batch[key] = (st, p, r, leaf)

        flagged = False
        try:
            for li in self.frontier:
                cur, p, rank = self.states[li], self.pos[li], 0
                m.run_next(cur, on_succ)
                if rank == 0 and m.check_deadlock:
                    raise _Flag()
                if rank >> RANK_BITS:
                    raise _Flag()  # cannot be numbered; the replay handles the level
                generated += rank
        except _Flag:
            flagged = True
        except Exception:  # an evaluation error (or a recursion): the replay reports it exactly
            flagged = True
        for dest, batch in enumerate(outgoing):
            if dest != me:
                entries = list(batch.items()) if keyed else list(batch.values())
                with open(self._path("B", me, dest), "wb") as f:
                    pickle.dump(entries, f, protocol=pickle.HIGHEST_PROTOCOL)
        return flagged, generated

    def _merge(self, candidates: dict) -> tuple[bool, list[int], array]:
        """Phase 2.  Returns (flagged, local indices of the new states in BFS order,
        their sort keys)."""
        m, seen = self.m, self.seen
        keyed = m.view is not None or m.symmetry is not None
        for src in range(self.n):
            if src == self.me:
                continue
            path = self._path("B", src, self.me)
            with open(path, "rb") as f:
                entries = pickle.load(f)
            os.unlink(path)
            for entry in entries:
                key, c = entry if keyed else (entry[0], entry)
                if key in seen:
                    continue
                old = candidates.get(key)
                if old is None or (c[1], c[2]) < (old[1], old[2]):
                    candidates[key] = c
        ordered = sorted(candidates.items(), key=lambda kc: (kc[1][1], kc[1][2]))
        sort_keys = array("q", [(c[1] << RANK_BITS) | c[2] for _, c in ordered])
        with open(self._path("K", self.me), "wb") as f:
            sort_keys.tofile(f)
        new: list[int] = []
        flagged = False
        next_level = self.depth + 1
        try:
            for key, (st, p, _, leaf) in ordered:
                seen.add(key)
                new.append(self._store(st, next_level, -1, p, leaf))
                for inv in m.invariants:
                    if not m.holds(inv, st):
                        raise _Flag()
        except Exception:
            flagged = True
        return flagged, new, sort_keys

    def _number(self, new: list[int], sort_keys: array) -> None:
        """Phase 3: positions of the new states in the next level; they become the frontier."""
        others = []
        for src in range(self.n):
            if src != self.me:
                keys = array("q")
                with open(self._path("K", src), "rb") as f:
                    keys.frombytes(f.read())
                others.append(keys)
        for i, li in enumerate(new):
            k = sort_keys[i]
            self.pos[li] = i + sum(bisect_left(o, k) for o in others)
        self.frontier = new
        self.depth += 1

    def _stop(self, decision: str) -> None:
        """The coordinator stops the search; on "dump" it replays the level being
        expanded, so it gets every stored state of that level and the ones before."""
        if decision == "dump":
            keep = bisect_right(self.level, self.depth)
            path = self._path("D", self.me)
            with open(path, "wb") as f:
                pickle.dump((self.states[:keep], self.level[:keep], self.pos[:keep], self.ppos[:keep],
                             self.leaf[:keep]), f, protocol=pickle.HIGHEST_PROTOCOL)
            self.conn.send((path,))
