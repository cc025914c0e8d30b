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
    def __init__(self, ray: Any, me: int, checkpoints: str | None = None) -> None:
        self.ray = ray
        self.me = me
        self.checkpoints = checkpoints  # the folder of the shards' checkpoint files
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

    def save(self, depth: int, saved: tuple) -> None:
        """The shard's checkpoint of level `depth`, written whole before it is named (the
        coordinator removes the older levels' once every shard has written this one)."""
        if self.checkpoints is None:
            raise RuntimeError("a checkpoint was asked for, but no checkpoint folder was given")
        path = checkpoint_file(self.checkpoints, self.me, depth)
        tmp = f"{path}.{os.getpid()}.tmp"
        with open(tmp, "wb") as f:
            pickle.dump(saved, f, protocol=pickle.HIGHEST_PROTOCOL)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)


def checkpoint_file(folder: str, me: int, depth: int | str) -> str:
    """Shard `me`'s checkpoint of level `depth` (or "*": a glob pattern of all its levels')."""
    return os.path.join(folder, f"shard-{me}-level-{depth}.pkl")


class ShardActor:
    """One shard of the search (made a Ray actor class by `ray_search.actor_class`)."""

    def __init__(self, files: dict[str, bytes], main: str, cfg: str, me: int, n: int, max_memory_mb: float,
                 initial: bytes, checkpoints: str | None = None, resume_depth: int = 0) -> None:
        """`checkpoints`: the folder of the shards' checkpoint files (on a disk every
        machine of the cluster reaches); `resume_depth` > 0: start from this shard's
        checkpoint there, which must be of that level."""
        import ray
        self.folder = tempfile.mkdtemp(prefix="safestate-ray-shard-")
        for name, data in files.items():
            with open(os.path.join(self.folder, name), "wb") as f:
                f.write(data)
        self.link = RayLink(ray, me, checkpoints)
        self.args = (os.path.join(self.folder, main), os.path.join(self.folder, cfg), me, n, max_memory_mb,
                     pickle.loads(initial), resume_depth)
        threading.Thread(target=self._main, daemon=True).start()

    def _main(self) -> None:
        from ..checker.deep_stack import call_with_deep_stack
        from ..checker.model import load_model
        from ..checker.shard_worker import ShardWorker
        tla, cfg, me, n, max_memory_mb, initial, resume_depth = self.args
        try:
            model = load_model(tla, cfg)
            saved = None
            if resume_depth:
                assert self.link.checkpoints is not None
                with open(checkpoint_file(self.link.checkpoints, me, resume_depth), "rb") as f:
                    saved = pickle.load(f)
            worker = ShardWorker(model, me, n, self.link, max_memory_mb)
            call_with_deep_stack(lambda: worker.run(initial, saved))
        except BaseException as e:  # a defect: the coordinator searches again with one worker
            self.link.reports.put((("crash", f"{type(e).__name__}: {e}"), None))

    def report(self) -> tuple[tuple, Any]:
        return self.link.reports.get()

    def decide(self, decision: str, incoming: list) -> None:
        self.link.decisions.put((decision, incoming))

    def pid(self) -> int:
        return os.getpid()
