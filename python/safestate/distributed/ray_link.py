"""The worker side: a Ray actor that loads the model from its text and runs one
`ShardWorker` on a thread of its own, linked to the coordinator by two queues.

The coordinator calls `report()` (blocks until the worker reaches its next barrier)
and `decide()`; the batches and key arrays a worker sends are put in Ray's object store
and travel as references: with the report to the coordinator, then with the decision
to the worker that owns them.  A worker's stored states go to the coordinator as a
plain pickle (its process hashes with another seed).
"""

from __future__ import annotations

import io
import os
import pickle
import queue
import tempfile
import threading
from array import array
from collections.abc import Iterator
from typing import Any


class RayLink:
    def __init__(self, ray: Any) -> None:
        self.ray = ray
        self.reports: queue.Queue[tuple[tuple, Any]] = queue.Queue()
        self.decisions: queue.Queue[tuple[str, list]] = queue.Queue()
        self.out_batches: dict[int, Any] = {}
        self.out_keys: Any = None
        self.incoming: list = []

    def barrier(self, report: tuple) -> str:
        payload = self.out_keys if self.out_keys is not None else dict(self.out_batches)
        self.out_batches, self.out_keys = {}, None
        self.reports.put((report, payload))
        decision, self.incoming = self.decisions.get()
        return decision

    def send_batch(self, depth: int, dest: int, entries: list) -> None:
        from ..checker.shard_worker import dump_between_workers
        f = io.BytesIO()
        dump_between_workers(entries, f)
        self.out_batches[dest] = self.ray.put(f.getvalue())

    def batches(self, depth: int) -> Iterator[list]:
        for ref in self.incoming:
            entries: list = pickle.loads(self.ray.get(ref))
            yield entries

    def send_keys(self, depth: int, keys: array) -> None:
        self.out_keys = self.ray.put(keys.tobytes())

    def keys(self, depth: int) -> list[array]:
        out = []
        for ref in self.incoming:
            keys = array("q")
            keys.frombytes(self.ray.get(ref))
            out.append(keys)
        return out

    def level_done(self, depth: int) -> None:
        pass  # the object store frees an array once no reference to it is left

    def dump(self, stored: tuple) -> None:
        self.reports.put(((self.ray.put(pickle.dumps(stored, protocol=pickle.HIGHEST_PROTOCOL)),), None))


class ShardActor:
    """One shard of the search (made a Ray actor class by `ray_search.actor_class`)."""

    def __init__(self, files: dict[str, bytes], main: str, cfg: str, me: int, n: int, max_memory_mb: float,
                 initial: bytes) -> None:
        import ray
        self.folder = tempfile.mkdtemp(prefix="safestate-ray-shard-")
        for name, data in files.items():
            with open(os.path.join(self.folder, name), "wb") as f:
                f.write(data)
        self.link = RayLink(ray)
        self.args = (os.path.join(self.folder, main), os.path.join(self.folder, cfg), me, n, max_memory_mb,
                     pickle.loads(initial))
        threading.Thread(target=self._main, daemon=True).start()

    def _main(self) -> None:
        from ..checker.deep_stack import call_with_deep_stack
        from ..checker.model import load_model
        from ..checker.shard_worker import ShardWorker
        tla, cfg, me, n, max_memory_mb, initial = self.args
        try:
            model = load_model(tla, cfg)
            call_with_deep_stack(lambda: ShardWorker(model, me, n, self.link, max_memory_mb).run(initial))
        except BaseException as e:  # a defect: the coordinator searches again with one worker
            self.link.reports.put((("crash", f"{type(e).__name__}: {e}"), None))

    def report(self) -> tuple[tuple, Any]:
        return self.link.reports.get()

    def decide(self, decision: str, incoming: list) -> None:
        self.link.decisions.put((decision, incoming))

    def pid(self) -> int:
        return os.getpid()
