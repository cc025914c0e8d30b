"""The coordinator of the search on Ray: `ParallelExplorer`'s barrier protocol, with Ray
actors (`ray_link.ShardActor`) as the workers.

Each actor gets the model's text (every module it loads from the model's folder and the
cfg), not a fork of this process, so it runs on any machine of the cluster that has
safestate installed.  `RayConn` gives the coordinator the pipe it expects: `recv()`
is the actor's next report, `send()` its decision, with the object references of the
batches (after the expansion) or key arrays (after the merge) the other actors sent it.
A worker that dies or fails ends the sharded search; the coordinator then searches
again with one worker, as `parallel.py` does, so the result is the same.
"""

from __future__ import annotations

import glob
import hashlib
import json
import os
import pickle
import sys
import time
from dataclasses import dataclass
from typing import Any, Callable

from ..checker.explore import Explorer
from ..checker.model import Model
from ..checker.parallel import ParallelExplorer, _Fallback
from ..errors import UsageError
from .cluster import connect, one_line
from .ray_link import ShardActor, checkpoint_file


@dataclass(frozen=True)
class RayTarget:
    """Where to search (`--ray`), the files each worker loads the model from, and where
    the shards keep their checkpoints (`--checkpoint DIR`, every `checkpoint_seconds`;
    `resume`: go on from the checkpoint there)."""

    address: str
    model_path: str
    cfg_path: str
    checkpoints: str | None = None
    checkpoint_seconds: float = 60.0
    resume: bool = False


MANIFEST = "search.json"
RESTARTS = 3  # failed workers replaced from the last checkpoint at most this often


class _Router:
    """The payloads of the last gathered phase, by worker: batch references by owner
    (after the expansion) or the key-array reference (after the merge)."""

    def __init__(self, n: int) -> None:
        self.payload: list[Any] = [None] * n

    def incoming(self, me: int, decision: str) -> list:
        others = [p for i, p in enumerate(self.payload) if i != me]
        if decision == "merge":
            return [p[me] for p in others]
        if decision == "number":
            return others
        return []


class RayConn:
    def __init__(self, ray: Any, actor: Any, me: int, router: _Router) -> None:
        self.ray, self.actor, self.me, self.router = ray, actor, me, router

    def recv(self) -> tuple:
        try:
            report, payload = self.ray.get(self.actor.report.remote())
        except self.ray.exceptions.RayError as e:
            raise EOFError(one_line(e)) from None
        self.router.payload[self.me] = payload
        return tuple(report)

    def send(self, decision: str) -> None:
        self.actor.decide.remote(decision, self.router.incoming(self.me, decision))


def model_texts(model: Model, target: RayTarget) -> tuple[dict[str, bytes], str, str]:
    """{file name: bytes} of the model's own modules and its cfg (as read, whatever their
    encoding), and the names of the root module and the cfg among them."""
    folder = os.path.dirname(os.path.abspath(target.model_path))
    files: dict[str, bytes] = {}
    for path in {*model.module_files, target.model_path}:
        if os.path.dirname(os.path.abspath(path)) == folder:
            with open(path, "rb") as f:
                files[os.path.basename(path)] = f.read()
    cfg = "__ray__" + os.path.basename(target.cfg_path)
    with open(target.cfg_path, "rb") as f:
        files[cfg] = f.read()
    return files, os.path.basename(target.model_path), cfg


class RayExplorer(ParallelExplorer):
    def __init__(self, model: Model, graph: bool, max_memory_mb: int | None,
                 progress: Callable[[str], None] | None, workers: int, target: RayTarget) -> None:
        super().__init__(model, graph, max_memory_mb, progress, workers)
        self.target = target
        self.worker_pids: list[int] = []
        self.actors: list[Any] = []
        self.files: tuple[dict[str, bytes], str, str] = ({}, "", "")
        self.blob = b""
        self.last_checkpoint = 0.0
        self.checkpoint_pending = False
        # In the caller's thread (the search runs on another): Ray installs its signal
        # handlers there.
        self.ray, self.owned = connect(target.address, workers)
        cpus = int(self.ray.cluster_resources().get("CPU", 0))
        if cpus < workers:
            self._disconnect()
            raise UsageError(f"--ray {target.address}: the cluster has {cpus} CPU(s); --workers {workers} "
                             f"needs one per worker")

    def _expand_all(self) -> None:
        try:
            if not self.states:
                return
            initial = list(self.states)
            self._init_generated = self.generated
            self.files = model_texts(self.m, self.target)
            self.blob = pickle.dumps(initial, protocol=pickle.HIGHEST_PROTOCOL)
            start = self._resume_point() if self.target.resume else None
            for attempt in range(RESTARTS + 1):
                conns = self._start_workers(start)
                try:
                    self._coordinate(conns, *(start[:2] if start else ()))  # type: ignore[arg-type]
                    break
                except _Fallback as why:
                    self._stop_workers()
                    start = self._last_checkpoint() if attempt < RESTARTS else None
                    if start is None:
                        print(f"safestate check: the search on Ray failed ({why}); searching again with one "
                              f"worker", file=sys.stderr, flush=True)
                        self._restart_sequential(initial)
                        break
                    print(f"safestate check: the search on Ray failed ({why}); new workers go on from the "
                          f"checkpoint of level {start[1]}", file=sys.stderr, flush=True)
        finally:
            self._stop_workers()
            self._disconnect()
        if self.outcome is None and self.head < len(self.states):
            Explorer._expand_all(self)  # the level replayed sequentially, and any after it

    def _start_workers(self, start: tuple[int, int, int] | None) -> list[RayConn]:
        """New actors, from the initial states or from the checkpoint (distinct, depth, generated)."""
        files, main, cfg = self.files
        actor_class = self.ray.remote(num_cpus=1, max_concurrency=2)(ShardActor)
        if start is not None:
            self.generated, self.max_level = start[2], start[1]
        self.actors = [actor_class.remote(files, main, cfg, me, self.workers, self.max_memory_mb, self.blob,
                                          self.target.checkpoints, start[1] if start else 0)
                       for me in range(self.workers)]
        self.worker_pids = self.ray.get([a.pid.remote() for a in self.actors])
        self.last_checkpoint = time.monotonic()
        router = _Router(self.workers)
        return [RayConn(self.ray, a, me, router) for me, a in enumerate(self.actors)]

    def _stop_workers(self) -> None:
        for a in self.actors:
            try:
                self.ray.kill(a)
            except Exception:  # already gone
                pass
        self.actors = []

    # ---------------------------------------------------------------- checkpoints
    def _number_decision(self) -> str:
        if self.target.checkpoints and time.monotonic() - self.last_checkpoint >= self.target.checkpoint_seconds:
            self.last_checkpoint = time.monotonic()
            self.checkpoint_pending = True
            return "checkpoint"
        return "number"

    def _level_started(self, depth: int, distinct: int) -> None:
        # Each worker saved its shard before expanding this level: the checkpoint is whole.
        folder = self.target.checkpoints
        if not (self.checkpoint_pending and folder):
            return
        self.checkpoint_pending = False
        data = {"identity": self._identity(), "workers": self.workers, "depth": depth, "distinct": distinct,
                "generated": self.generated}
        path = os.path.join(folder, MANIFEST)
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            json.dump(data, f)
        os.replace(path + ".tmp", path)
        for me in range(self.workers):  # the older levels' files: this one is whole now
            for old in glob.glob(checkpoint_file(folder, me, "*") + "*"):  # and any partial .tmp
                if old != checkpoint_file(folder, me, depth):
                    os.remove(old)

    def _identity(self) -> str:
        """What a checkpoint belongs to: the model's files and cfg, as the workers load them."""
        files, main, cfg = self.files
        h = hashlib.sha256(f"{main}\0{cfg}\0".encode())
        for name in sorted(files):
            h.update(name.encode() + b"\0" + files[name] + b"\0")
        return h.hexdigest()

    def _last_checkpoint(self) -> tuple[int, int, int] | None:
        """(distinct, depth, generated) of the last whole checkpoint of this search, or None."""
        if not self.target.checkpoints:
            return None
        try:
            with open(os.path.join(self.target.checkpoints, MANIFEST), encoding="utf-8") as f:
                d = json.load(f)
        except (OSError, ValueError):
            return None
        if d.get("identity") != self._identity() or d.get("workers") != self.workers:
            return None
        return int(d["distinct"]), int(d["depth"]), int(d["generated"])

    def _resume_point(self) -> tuple[int, int, int]:
        start = self._last_checkpoint()
        if start is None:
            raise UsageError(f"--resume {self.target.checkpoints}: no checkpoint of this model and cfg with "
                             f"--workers {self.workers} there")
        return start

    def _disconnect(self) -> None:
        if self.owned:
            self.ray.shutdown()

    @staticmethod
    def _read_dump(reply: tuple) -> Any:
        import ray
        return pickle.loads(ray.get(reply[0]))

    def cpu_report(self, coordinator_cpu: float) -> dict:
        return {**super().cpu_report(coordinator_cpu), "ray": self.target.address}
