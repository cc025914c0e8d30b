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

How the batches, the key arrays and the barrier messages travel is the worker's
`ShardLink` (`shard_link.py`): files in shared memory and a pipe on one machine, Ray's
object store across machines (`distributed/`).
"""

from __future__ import annotations

import copyreg
import pickle
import time
from array import array
from bisect import bisect_left
from typing import Any

from ..tla.enum_watch import rss_mb
from ..tla.env import UNSET
from ..tla.values import FnValue, same_kinds
from .model import Model
from .shard_link import ShardLink

RANK_BITS = 32  # a sort key packs (position in level, rank) into one signed 64-bit int


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


def _fn_with_hash(d: dict, h: int) -> FnValue:
    fv = FnValue(d)
    fv._hash = h
    return fv


def _reduce_fn(fv: FnValue) -> tuple:
    return (_fn_with_hash, (fv.d, hash(fv)))


# Records and functions travel with their hash: every worker hashes alike (a fork of the
# same process, or a Ray actor started with the same PYTHONHASHSEED; model values hash
# by name), so the receiver need not rebuild a frozenset per record to hash it again.
# Only between workers: a pickle read by another process (the graph cache, a Ray
# coordinator) must not carry hashes.
_DISPATCH = dict(copyreg.dispatch_table)
_DISPATCH[FnValue] = _reduce_fn


def dump_between_workers(obj: Any, f: Any) -> None:
    """Pickles `obj` to the binary file `f`, records and functions with their hash."""
    pickler = pickle.Pickler(f, protocol=pickle.HIGHEST_PROTOCOL)
    pickler.dispatch_table = _DISPATCH
    pickler.dump(obj)


class _Flag(Exception):
    """Ends the expansion: something a single worker stops at; the level is replayed."""


class ShardWorker:
    def __init__(self, model: Model, me: int, n: int, link: ShardLink, max_memory_mb: float) -> None:
        self.m = model
        self.me = me
        self.n = n
        self.link = link
        self.keyed = model.view is not None or model.symmetry is not None
        # The shards split the states evenly, so each worker gets an even share of the limit.
        self.memory_share_mb = max_memory_mb / n
        # key -> the state's local index once stored, or its best candidate
        # (sort key, state, leaf[, key]) during the level that discovers it.
        self.known: dict[Any, Any] = {}
        self.states: list[tuple] = []
        self.level_start = [0, 0]  # local index of each level's first state (levels from 1)
        self.pos = array("q")      # position in its level's global BFS order
        self.ppos = array("q")     # the parent's position in the previous level
        self.leaf = array("i")
        self.depth = 1             # the level being expanded
        self.memory_exceeded = False
        self.phase_start = time.process_time()

    # ---------------------------------------------------------------- helpers
    def _barrier(self, flagged: bool, count: int) -> str:
        """Report this phase (with the CPU seconds it took), wait for the coordinator's decision."""
        now = time.process_time()
        decision = self.link.barrier((flagged, self.memory_exceeded, count, now - self.phase_start))
        self.phase_start = time.process_time()
        return decision

    def _check_memory(self) -> None:
        if pss_mb() > self.memory_share_mb:
            self.memory_exceeded = True
            raise _Flag()

    # ---------------------------------------------------------------- the search
    def run(self, initial: list[tuple], saved: tuple | None = None) -> None:
        """The search from the initial states, or from a checkpoint (`saved()` of an
        earlier worker with the same shard, at the end of a level)."""
        m = self.m
        if saved is not None:
            (self.depth, self.known, self.states, self.level_start, self.pos, self.ppos, self.leaf) = saved
        for p, st in enumerate(initial if saved is None else []):
            key = m.key(st) if self.keyed else st
            if hash(key) % self.n == self.me:
                self.known[key] = len(self.states)
                self.states.append(st)
                self.pos.append(p)
                self.ppos.append(-1)
                self.leaf.append(-1)
        if saved is None:
            self.level_start.append(len(self.states))
        while True:
            fresh: list = []
            flagged, generated = self._expand(fresh)
            decision = self._barrier(flagged, generated)
            if self.depth > 1:  # every worker has read the previous level's key arrays
                self.link.level_done(self.depth - 1)
            if decision != "merge":
                return self._stop(decision)
            flagged, new = self._merge(fresh)
            decision = self._barrier(flagged, new)
            if decision not in ("number", "checkpoint"):
                return self._stop(decision)
            self._number()
            if decision == "checkpoint":
                self.link.save(self.depth, self.saved())

    def saved(self) -> tuple:
        """Everything the shard holds between two levels: what `run` resumes from."""
        return (self.depth, self.known, self.states, self.level_start, self.pos, self.ppos, self.leaf)

    def _expand(self, fresh: list) -> tuple[bool, int]:
        """Phase 1: expand the level's states; `fresh` gets the keys of the new owned
        candidates.  Returns (flagged, states generated)."""
        m, me, n, keyed = self.m, self.me, self.n, self.keyed
        known = self.known
        constrained = bool(m.constraints or m.action_constraints)
        invariants, action_properties, holds = m.invariants, m.action_properties, m.holds
        outgoing: list[dict] = [{} for _ in range(n)]
        cur: tuple = ()
        base = rank = 0
        states_ = self.states

        def stored_key(old: Any) -> Any:
            """The key `known` holds for an index or a candidate."""
            if type(old) is int:
                return m.key(states_[old]) if keyed else states_[old]
            return old[3] if keyed else old[1]

        def on_succ(st: tuple, leaf: int, L: list) -> None:
            # The hot path: kept to the checks that apply, as Explorer.expand's on_succ.
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
            if keyed:
                key = m.key(st)
                dest = hash(key) % n
                if dest == me:
                    old = known.get(key)
                    if old is None:
                        known[key] = (base + r, st, leaf, key)
                        fresh.append(key)
                    elif not same_kinds(key, stored_key(old)):
                        raise _Flag()
                else:
                    batch = outgoing[dest]
                    old = batch.get(key)
                    if old is None:
                        batch[key] = (base + r, st, leaf, key)
                    elif not same_kinds(key, old[3]):
                        raise _Flag()
                return
            dest = hash(st) % n
            if dest == me:
                old = known.get(st)
                if old is None:
                    known[st] = (base + r, st, leaf)
                    fresh.append(st)
                elif not same_kinds(st, stored_key(old)):
                    raise _Flag()
            else:
                batch = outgoing[dest]
                old = batch.get(st)
                if old is None:
                    batch[st] = (base + r, st, leaf)
                elif not same_kinds(st, old[1]):
                    raise _Flag()

        flagged = False
        generated = 0
        states, pos = self.states, self.pos
        deadlock = m.check_deadlock
        try:
            for li in range(self.level_start[self.depth], len(states)):
                cur, base, rank = states[li], pos[li] << RANK_BITS, 0
                if not li & 4095:
                    self._check_memory()
                m.run_next(cur, on_succ)
                if rank == 0 and deadlock:
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
                self.link.send_batch(self.depth, dest, list(batch.values()))
        return flagged, generated

    def _merge(self, fresh: list) -> tuple[bool, int]:
        """Phase 2: merge the batches sent here, store the new states in BFS order and
        check the invariants on them.  Returns (flagged, number of new states)."""
        m, known, keyed = self.m, self.known, self.keyed
        for entries in self.link.batches(self.depth):
            for c in entries:
                key = c[3] if keyed else c[1]
                old = known.get(key)
                if old is None:
                    known[key] = c
                    fresh.append(key)
                    continue
                stored = (old[3] if keyed else old[1]) if type(old) is tuple else (
                    m.key(self.states[old]) if keyed else self.states[old])
                if not same_kinds(key, stored):
                    # Equal to Python only (TRUE and 1): the level is replayed by one
                    # process, whose state table tells them apart (explore.py).
                    return True, 0
                if type(old) is tuple and c[0] < old[0]:
                    known[key] = c
        # Sort keys are unique, so the candidates sort by them alone.
        ordered = sorted([known[k] for k in fresh])
        first = len(self.states)
        if keyed:
            for i, c in enumerate(ordered):
                known[c[3]] = first + i
        else:
            for i, c in enumerate(ordered):
                known[c[1]] = first + i
        sort_keys = array("q", [c[0] for c in ordered])
        self.link.send_keys(self.depth, sort_keys)
        new_states = [c[1] for c in ordered]
        self.states.extend(new_states)
        self.ppos.extend(array("q", [c[0] >> RANK_BITS for c in ordered]))
        self.leaf.extend(array("i", [c[2] for c in ordered]))
        self.sort_keys = sort_keys
        flagged = False
        try:
            self._check_memory()
            holds = m.holds
            for inv in m.invariants:
                for st in new_states:
                    if not holds(inv, st):
                        raise _Flag()
        except Exception:
            flagged = True
        return flagged, len(ordered)

    def _number(self) -> None:
        """Phase 3: positions of the new states in the next level (their rank among every
        worker's new sort keys); they become the level to expand."""
        others = self.link.keys(self.depth)
        sort_keys = self.sort_keys
        if len(others) == 1:
            other = others[0]
            self.pos.extend(array("q", [i + bisect_left(other, k) for i, k in enumerate(sort_keys)]))
        else:
            self.pos.extend(array("q", [i + sum(bisect_left(o, k) for o in others)
                                        for i, k in enumerate(sort_keys)]))
        self.depth += 1
        self.level_start.append(len(self.states))

    def _stop(self, decision: str) -> None:
        """The coordinator stops the search; on "dump" it replays the level being
        expanded, so it gets every stored state of that level and the ones before."""
        if decision == "dump":
            keep = self.level_start[self.depth + 1]
            levels = array("i")
            for lv in range(1, self.depth + 1):
                levels.extend(array("i", [lv]) * (self.level_start[lv + 1] - self.level_start[lv]))
            self.link.dump((self.states[:keep], levels, self.pos[:keep], self.ppos[:keep], self.leaf[:keep]))
