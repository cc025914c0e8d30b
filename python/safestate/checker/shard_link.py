"""How the workers of the sharded search (`shard_worker.py`) reach each other and the
coordinator: per BFS level, one batch of candidate states from every worker to every
other, one array of sort keys from every worker to all, and a barrier message to the
coordinator at the end of each phase.

`PipeLink` is the one-machine link of `parallel.py`: the batches and key arrays are
files in a shared-memory folder, the barrier is a pipe.  The Ray link
(`distributed/ray_link.py`) carries the same data through Ray's object store.
"""

from __future__ import annotations

import os
import pickle
from array import array
from collections.abc import Iterator
from multiprocessing.connection import Connection
from typing import Any, Protocol


class ShardLink(Protocol):
    def barrier(self, report: tuple) -> str:
        """Sends the phase's report to the coordinator; its decision."""

    def send_batch(self, depth: int, dest: int, entries: list) -> None:
        """The candidates of level `depth` owned by worker `dest` (every other worker gets one)."""

    def batches(self, depth: int) -> Iterator[list]:
        """The batches the other workers sent this worker at `depth`, in worker order."""

    def send_keys(self, depth: int, keys: array) -> None:
        """This worker's sorted sort keys of the new states of `depth`."""

    def keys(self, depth: int) -> list[array]:
        """The other workers' sort keys of `depth`, in worker order."""

    def level_done(self, depth: int) -> None:
        """Every worker has read the key arrays of `depth`."""

    def dump(self, stored: tuple) -> None:
        """Sends the stored states (for the coordinator's sequential replay)."""

    def save(self, depth: int, saved: tuple) -> None:
        """Keeps the shard's checkpoint at the start of level `depth` (`ShardWorker.saved`)."""


class PipeLink:
    """Files in a shared folder (RAM under /dev/shm) and a pipe to the coordinator; the
    workers are forks of the coordinator, so pickles may carry hashes."""

    def __init__(self, me: int, n: int, folder: str, conn: Connection) -> None:
        self.me, self.n, self.folder, self.conn = me, n, folder, conn

    def _path(self, kind: str, depth: int, src: int, dst: int = 0) -> str:
        return os.path.join(self.folder, f"{kind}{depth}_{src}_{dst}")

    def barrier(self, report: tuple) -> str:
        self.conn.send(report)
        decision: str = self.conn.recv()
        return decision

    def send_batch(self, depth: int, dest: int, entries: list) -> None:
        from .shard_worker import dump_between_workers
        with open(self._path("B", depth, self.me, dest), "wb") as f:
            dump_between_workers(entries, f)

    def batches(self, depth: int) -> Iterator[list]:
        for src in range(self.n):
            if src != self.me:
                path = self._path("B", depth, src, self.me)
                with open(path, "rb") as f:
                    entries: list = pickle.load(f)
                os.unlink(path)
                yield entries

    def send_keys(self, depth: int, keys: array) -> None:
        with open(self._path("K", depth, self.me), "wb") as f:
            keys.tofile(f)

    def keys(self, depth: int) -> list[array]:
        out = []
        for src in range(self.n):
            if src != self.me:
                keys = array("q")
                with open(self._path("K", depth, src), "rb") as f:
                    keys.frombytes(f.read())
                out.append(keys)
        return out

    def level_done(self, depth: int) -> None:
        os.unlink(self._path("K", depth, self.me))

    def dump(self, stored: tuple) -> None:
        from .shard_worker import dump_between_workers
        path = self._path("D", 0, self.me)
        with open(path, "wb") as f:
            dump_between_workers(stored, f)
        self.conn.send((path,))

    def save(self, depth: int, saved: tuple) -> None:
        raise RuntimeError("the search on one machine keeps no checkpoints")


def read_dump(reply: tuple) -> Any:
    """The stored states a `PipeLink` worker dumped (its reply to "dump")."""
    with open(reply[0], "rb") as f:
        return pickle.load(f)
