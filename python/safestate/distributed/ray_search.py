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

import os
import pickle
import sys
from dataclasses import dataclass
from typing import Any, Callable

from ..checker.explore import Explorer
from ..checker.model import Model
from ..checker.parallel import ParallelExplorer, _Fallback
from ..errors import UsageError
from .cluster import connect, one_line
from .ray_link import ShardActor


@dataclass(frozen=True)
class RayTarget:
    """Where to search (`--ray`), and the files each worker loads the model from."""

    address: str
    model_path: str
    cfg_path: str


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
        # In the caller's thread (the search runs on another): Ray installs its signal
        # handlers there.
        self.ray, self.owned = connect(target.address, workers)
        cpus = int(self.ray.cluster_resources().get("CPU", 0))
        if cpus < workers:
            self._disconnect()
            raise UsageError(f"--ray {target.address}: the cluster has {cpus} CPU(s); --workers {workers} "
                             f"needs one per worker")

    def _expand_all(self) -> None:
        ray = self.ray
        actors: list[Any] = []
        try:
            if not self.states:
                return
            files, main, cfg = model_texts(self.m, self.target)
            initial = list(self.states)
            self._init_generated = self.generated
            blob = pickle.dumps(initial, protocol=pickle.HIGHEST_PROTOCOL)
            actor_class = ray.remote(num_cpus=1, max_concurrency=2)(ShardActor)
            actors = [actor_class.remote(files, main, cfg, me, self.workers, self.max_memory_mb, blob)
                      for me in range(self.workers)]
            self.worker_pids = ray.get([a.pid.remote() for a in actors])
            router = _Router(self.workers)
            conns = [RayConn(ray, a, me, router) for me, a in enumerate(actors)]
            try:
                self._coordinate(conns)  # type: ignore[arg-type]
            except _Fallback as why:
                print(f"safestate check: the search on Ray failed ({why}); searching again with one worker",
                      file=sys.stderr, flush=True)
                self._restart_sequential(initial)
        finally:
            for a in actors:
                try:
                    ray.kill(a)
                except Exception:  # already gone
                    pass
            self._disconnect()
        if self.outcome is None and self.head < len(self.states):
            Explorer._expand_all(self)  # the level replayed sequentially, and any after it

    def _disconnect(self) -> None:
        if self.owned:
            self.ray.shutdown()

    @staticmethod
    def _read_dump(reply: tuple) -> Any:
        import ray
        return pickle.loads(ray.get(reply[0]))

    def cpu_report(self, coordinator_cpu: float) -> dict:
        return {**super().cpu_report(coordinator_cpu), "ray": self.target.address}
