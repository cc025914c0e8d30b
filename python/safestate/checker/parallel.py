"""Breadth-first search on several cores: the fingerprint space sharded over worker processes.

The coordinator (this process) computes the initial states as one worker does, then
forks ``n`` workers (`shard_worker.py`); worker ``i`` owns the states whose key hashes
to ``i`` modulo ``n`` and keeps their seen-set and queue.  The search is
level-synchronous: per BFS level each worker expands its states, sends the successors
owned by another worker in one batch per owner (a file in shared memory), merges the
batches sent to it and numbers its new states; the coordinator is a barrier that only
adds up counts.  No state passes through the coordinator, so the workers' CPU is the
search's CPU.

Results are those of one worker, by construction:

* distinct/generated counts and depth of a complete search do not depend on the order
  of expansion;
* every state is numbered by its place in a single worker's BFS order (its parent's
  place, then its rank among the parent's successors), and of several parents of a
  new state the first in that order is recorded, as one worker records it;
* when any worker meets something a single worker stops at (a violated invariant or
  action property, a deadlock, an evaluation error), the workers send their stored
  states, the coordinator rebuilds the single-worker search as it was at the start of
  that level and expands the level sequentially (`Explorer.expand`).  So the
  reported violation, its counts and its (shortest) trace are exactly the single
  worker's: of several violations at the same depth, the first in TLC's generation
  order.
"""

from __future__ import annotations

import atexit
import functools
import multiprocessing
import os
import shutil
import signal
import sys
import tempfile
import time
from array import array
from multiprocessing.connection import Connection
from typing import Any, Callable

from ..tla.errors import TlaError
from ..tla.values import exact_key
from . import explore
from .explore import CheckResult, Explorer
from .model import Model
from .shard_link import PipeLink, read_dump
from .shard_worker import ShardWorker


def _worker_main(model: Model, me: int, n: int, folder: str, conn: Connection, max_memory_mb: float,
                 initial: list[tuple]) -> None:
    # Ctrl-C (sent to the whole process group) and SIGTERM are the coordinator's to
    # handle: it stops the workers by closing their pipes and removes the shared folder.
    # A worker dying of them first would look like a crash (a sequential restart).
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    try:
        ShardWorker(model, me, n, PipeLink(me, n, folder, conn), max_memory_mb).run(initial)
    except BaseException as e:  # a defect: the coordinator searches again with one worker
        try:
            conn.send(("crash", f"{type(e).__name__}: {e}"))
        except OSError:
            pass
    finally:
        conn.close()


def shared_memory_dir() -> str | None:
    """Where the workers' batch files go: $SAFESTATE_SHM_DIR, else /dev/shm (RAM), else
    the temporary folder.  The coordinator removes its folder on every exit but SIGKILL
    (`_expand_all`'s `finally`; SIGTERM is turned into an exception by the CLI, and
    `deep_stack` forwards Ctrl-C and SIGTERM to the search thread)."""
    env = os.environ.get("SAFESTATE_SHM_DIR")
    if env:
        return env
    return "/dev/shm" if os.path.isdir("/dev/shm") else None


class _Fallback(Exception):
    """The sharded search failed (a worker crashed): search again with one worker."""


class ParallelExplorer(Explorer):
    def __init__(self, model: Model, graph: bool, max_memory_mb: int | None,
                 progress: Callable[[str], None] | None, workers: int) -> None:
        super().__init__(model, graph, max_memory_mb, progress)
        self.workers = workers
        # CPU seconds of each worker, and of the slowest worker summed over the phases
        # (the search's critical path: what wall time would be on idle cores).
        self.worker_cpu = [0.0] * workers
        self.critical_cpu = 0.0
        self.distinct_so_far = 0

    def _expand_all(self) -> None:
        if not self.states:
            return
        folder = tempfile.mkdtemp(prefix="safestate-bfs-", dir=shared_memory_dir())
        remove = functools.partial(shutil.rmtree, folder, ignore_errors=True)
        atexit.register(remove)
        ctx = multiprocessing.get_context("fork")
        conns: list[Connection] = []
        procs = []
        initial = list(self.states)
        self._init_generated = self.generated
        try:
            for me in range(self.workers):
                ours, theirs = ctx.Pipe()
                proc = ctx.Process(target=_worker_main, daemon=True,
                                   args=(self.m, me, self.workers, folder, theirs, self.max_memory_mb, initial))
                proc.start()
                theirs.close()
                conns.append(ours)
                procs.append(proc)
            try:
                self._coordinate(conns)
            except _Fallback as why:
                print(f"safestate check: the parallel search failed ({why}); searching again with one worker",
                      file=sys.stderr, flush=True)
                self._restart_sequential(initial)
        except BaseException:
            # Stopped (Ctrl-C, SIGTERM, an error of ours): the workers are mid-level and
            # hold copies of every pipe, so closing ours would not end them -- kill them.
            for proc in procs:
                proc.kill()
            raise
        finally:
            # Ctrl-C or SIGTERM may arrive in here too (forwarded to this thread): the
            # folder is removed whatever happens, and at exit if even that is cut short.
            try:
                for c in conns:
                    c.close()
                for proc in procs:
                    proc.join(timeout=10)
                    if proc.is_alive():
                        proc.kill()
                        proc.join()
            finally:
                shutil.rmtree(folder, ignore_errors=True)
                atexit.unregister(remove)
        if self.outcome is None and self.head < len(self.states):
            Explorer._expand_all(self)  # the level replayed sequentially, and any after it

    def cpu_report(self, coordinator_cpu: float) -> dict:
        """`--json`'s "parallel": the workers' CPU and the critical path's (with this process's)."""
        return {"workers": self.workers, "worker_cpu_seconds": [round(c, 3) for c in self.worker_cpu],
                "coordinator_cpu_seconds": round(coordinator_cpu, 3),
                "critical_path_cpu_seconds": round(coordinator_cpu + self.critical_cpu, 3)}

    # ---------------------------------------------------------------- coordination
    def _gather(self, conns: list[Connection]) -> list[tuple]:
        replies = []
        for c in conns:
            try:
                r = c.recv()
            except EOFError:
                raise _Fallback("a worker process ended unexpectedly") from None
            if r[0] == "crash":
                raise _Fallback(r[1])
            replies.append(r)
        if len(replies[0]) == 4:
            # The phase ends when its slowest worker does: its CPU is on the critical path.
            self.critical_cpu += max(r[3] for r in replies)
            for i, r in enumerate(replies):
                self.worker_cpu[i] += r[3]
        return replies

    @staticmethod
    def _broadcast(conns: list[Connection], decision: str) -> None:
        for c in conns:
            c.send(decision)

    def _coordinate(self, conns: list[Connection], distinct: int = 0, depth: int = 1) -> None:
        """The barriers of the search from level `depth` with `distinct` states found
        (the initial states by default; a checkpoint's counts when resumed)."""
        distinct = distinct or len(self.states)
        while True:
            self.distinct_so_far = distinct  # for an interrupted search's report
            expanded = self._gather(conns)  # phase 1: (flagged, memory exceeded, generated, CPU s)
            self._level_started(depth, distinct)
            if self._memory_exceeded(conns, expanded, distinct, depth):
                return
            if any(r[0] for r in expanded):
                return self._replay(conns, depth)
            self._broadcast(conns, "merge")
            merged = self._gather(conns)  # phase 2: (flagged, memory exceeded, new states)
            if self._memory_exceeded(conns, merged, distinct, depth):
                return
            if any(r[0] for r in merged):
                return self._replay(conns, depth)
            self.generated += sum(r[2] for r in expanded)
            new = sum(r[2] for r in merged)
            if new == 0:
                self._broadcast(conns, "quit")
                self.outcome = CheckResult("success", distinct, self.generated, depth, 0)
                return
            distinct += new
            depth += 1
            self.max_level = depth
            self._broadcast(conns, self._number_decision())
            self._level_progress(depth, distinct, new)

    def _number_decision(self) -> str:
        """The decision that ends a level: "number", or "checkpoint" (number, then keep a
        checkpoint: the search on Ray)."""
        return "number"

    def _level_started(self, depth: int, distinct: int) -> None:
        """Every worker has started expanding level `depth` (after any checkpoint it kept)."""

    def _level_progress(self, depth: int, distinct: int, queued: int) -> None:
        now = time.monotonic()
        if self.progress is not None and now - self.last_progress >= explore.PROGRESS_SECONDS:
            self.last_progress = now
            self.progress(f"Progress({depth}): {self.generated} states generated, {distinct} distinct states "
                          f"found, {queued} states left on queue.")

    def _memory_exceeded(self, conns: list[Connection], replies: list[tuple], distinct: int, depth: int) -> bool:
        if not any(r[1] for r in replies):
            return False
        self._broadcast(conns, "quit")
        err = TlaError("memory", f"memory limit of {self.max_memory_mb} MB exceeded after {distinct} distinct "
                       f"states; raise it with --max-memory or add a state constraint")
        self.outcome = CheckResult("error", distinct, self.generated, depth, 0, error=err)
        return True

    # ---------------------------------------------------------------- sequential replay
    def _replay(self, conns: list[Connection], depth: int) -> None:
        """Rebuild the single-worker search at the start of level `depth` from the
        workers' stored states; `_expand_all` then expands that level sequentially."""
        self._broadcast(conns, "dump")
        parts = [self._read_dump(reply) for reply in self._gather(conns)]
        sizes = [0] * (depth + 2)
        for _, levels, _, _, _ in parts:
            for lv in levels:
                sizes[lv] += 1
        offset = [0] * (depth + 2)
        for lv in range(2, depth + 2):
            offset[lv] = offset[lv - 1] + sizes[lv - 1]
        total = offset[depth + 1]
        states: list[Any] = [None] * total
        parent = array("q", [-1]) * total
        leaf = array("i", [-1]) * total
        level = array("i", [0]) * total
        for sts, levels, pos, ppos, leaves in parts:
            for j, st in enumerate(sts):
                lv = levels[j]
                g = offset[lv] + pos[j]
                states[g] = st
                level[g] = lv
                if lv > 1:
                    parent[g] = offset[lv - 1] + ppos[j]
                    leaf[g] = leaves[j]
        self.states, self.parent, self.leaf, self.level = states, parent, leaf, level
        self._reseen(states)
        self.head = offset[depth]
        self.max_level = depth
        self.next_check = total

    @staticmethod
    def _read_dump(reply: tuple) -> Any:
        return read_dump(reply)

    def _reseen(self, states: list) -> None:
        """The state table of `states` (the workers flag a level where two states are
        equal to Python only, so these are distinct TLA+ states, see shard_worker.py)."""
        m = self.m
        keyed = m.view is not None or m.symmetry is not None
        keys = [m.key(st) for st in states] if keyed else states
        self.keys = keys if keyed else None
        self.exact_seen = {}
        self.seen = {}
        for g, k in enumerate(keys):
            if k in self.seen:
                self.exact_seen[exact_key(k)] = g
            else:
                self.seen[k] = g

    def _restart_sequential(self, initial: list[tuple]) -> None:
        """Back to the state after Init (level 1), for a search with one worker."""
        k = len(initial)
        self.states = initial
        del self.parent[k:], self.leaf[k:], self.level[k:]
        self._reseen(initial)
        self.head = 0
        self.max_level = 1
        self.generated = self._init_generated
        self.next_check = k
