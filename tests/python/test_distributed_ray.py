"""Issue 33: `safestate check --ray`, the search sharded over Ray actors, gives exactly
the single worker's result -- verdict, distinct/generated counts, depth, states left,
the violated property, the error and the counterexample trace -- on a local cluster of
two workers started here, on the loopback only; a worker killed mid-run still gives it."""

from __future__ import annotations

import importlib.util
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import cost_record
import pytest

from conftest import CORPUS, ERRORS, REPO, load_expected, run_safestate
from test_checker_parallel import WIDE
from safestate.checker import explore
from safestate.checker.explore import CheckResult, explore_states
from safestate.checker.model import default_config_path, load_model
from safestate.errors import UsageError

# Ray reads its authentication settings when it is imported: only the fixture imports it.
if importlib.util.find_spec("ray") is None:
    pytest.skip("Ray is not installed", allow_module_level=True)

from safestate.distributed.cluster import runtime_env  # noqa: E402
from safestate.distributed.ray_link import ShardActor  # noqa: E402
from safestate.distributed.ray_search import RayTarget  # noqa: E402


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture(scope="module")
def cluster() -> Iterator[str]:
    """A Ray head with two CPUs on 127.0.0.1 for this module, with token authentication
    (a fresh token in a 0600 file), joined by this process and the CLI runs it starts
    (its folder short: Ray's socket paths must fit in 107 bytes)."""
    temp = tempfile.mkdtemp(prefix="ssray", dir="/tmp")
    token = Path(temp) / "auth_token"
    token.write_text(secrets.token_hex(32))
    token.chmod(0o600)
    saved = {k: os.environ.get(k) for k in ("RAY_AUTH_MODE", "RAY_AUTH_TOKEN_PATH")}
    os.environ.update(RAY_AUTH_MODE="token", RAY_AUTH_TOKEN_PATH=str(token))
    import ray
    port = _free_port()
    address = f"127.0.0.1:{port}"
    exe = Path(sys.executable).with_name("ray")
    head = subprocess.Popen([str(exe), "start", "--head", "--block", "--node-ip-address", "127.0.0.1",
                             "--port", str(port), "--num-cpus", "2", "--include-dashboard", "false",
                             "--disable-usage-stats", "--temp-dir", temp],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    cost_record.COMPANION_SESSIONS.add(head.pid)  # the actors' CPU is the tests' cost
    try:
        deadline = time.monotonic() + 120
        while True:
            try:
                ray.init(address=address, runtime_env=runtime_env(), include_dashboard=False, log_to_driver=False,
                         configure_logging=False)
                break
            except Exception:
                if time.monotonic() > deadline or head.poll() is not None:
                    raise
                time.sleep(1)
        yield address
    finally:
        if ray.is_initialized():
            ray.shutdown()
        # The head alone: it stops its processes and exits in a few seconds (a SIGTERM to
        # its whole group leaves it waiting for them for longer than the 15 s below).
        os.kill(head.pid, signal.SIGTERM)

        def stop() -> None:
            try:
                head.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(head.pid, signal.SIGKILL)
                head.wait()
        cost_record.wait_for_companion(head.pid, stop)
        shutil.rmtree(temp, ignore_errors=True)
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


class ShardPool:
    """The two shard actors of the tests that only compare results: started once and
    handed to each search in turn (each search runs `ShardActor.__init__` on them again,
    with its own model text and initial states), instead of two new actor processes
    per search (their start, not the search, was most of such a test's time).  The
    tests that kill workers, keep checkpoints or run the CLI start their own actors
    (`own_actors`), as a user's search does."""

    def __init__(self) -> None:
        self.ray: Any = None
        self.actors: dict[int, Any] = {}

    def release(self) -> None:
        """Kill the pooled actors: their CPUs are the cluster's two."""
        for actor in self.actors.values():
            self.ray.kill(actor)
        self.actors = {}


class _PooledRay:
    """The `ray` module as `RayExplorer` sees it, except that its shard actors come from
    the pool and are kept there when the search ends."""

    def __init__(self, ray: Any, pool: ShardPool) -> None:
        self._ray, self._pool = ray, pool

    def __getattr__(self, name: str) -> Any:
        return getattr(self._ray, name)

    def remote(self, **options: Any) -> Callable[[type], Any]:
        return lambda cls: _PooledActorClass(self._ray.remote(**options)(cls), self._pool)

    def kill(self, actor: Any) -> None:
        if actor not in self._pool.actors.values():
            self._ray.kill(actor)


class _PooledActorClass:
    def __init__(self, actor_class: Any, pool: ShardPool) -> None:
        self.actor_class, self.pool = actor_class, pool

    def remote(self, *args: Any) -> Any:
        me = args[3]  # ShardActor(files, main, cfg, me, ...)
        actor = self.pool.actors.get(me)
        if actor is not None:
            try:
                self.pool.ray.get(actor.__ray_call__.remote(ShardActor.__init__, *args))
                return actor
            except self.pool.ray.exceptions.RayActorError:  # it died in an earlier search: a new one
                pass
        actor = self.pool.actors[me] = self.actor_class.remote(*args)
        return actor


@pytest.fixture(scope="module")
def shard_pool(cluster: str) -> Iterator[ShardPool]:
    import ray
    pool = ShardPool()
    pool.ray = ray
    yield pool
    pool.release()


@pytest.fixture
def pooled(cluster: str, shard_pool: ShardPool, monkeypatch: pytest.MonkeyPatch) -> str:
    """The cluster's address, with the searches' shard actors taken from the pool."""
    from safestate.distributed import ray_search
    real_connect = ray_search.connect

    def connect(address: str, workers: int) -> tuple[Any, bool]:
        ray, owned = real_connect(address, workers)
        return _PooledRay(ray, shard_pool), owned
    monkeypatch.setattr(ray_search, "connect", connect)
    return cluster


@pytest.fixture
def own_actors(cluster: str, shard_pool: ShardPool) -> str:
    """The cluster's address, its CPUs free of pooled actors: the test's search starts its own."""
    shard_pool.release()
    return cluster


def _outcome(r: CheckResult) -> tuple:
    trace = [(s.state, s.action, s.params) for s in r.trace or []]
    error = (r.error.kind, r.error.message) if r.error else None
    return (r.result, r.distinct_states, r.states_generated, r.depth, r.left_on_queue, r.violated, error, trace)


def _both(address: str, tla: Path, cfg: Path | None = None) -> tuple[tuple, tuple]:
    cfg_path = str(cfg) if cfg else default_config_path(str(tla))
    one = explore_states(load_model(str(tla), cfg_path), workers=1)
    sharded = explore_states(load_model(str(tla), cfg_path), workers=2,
                             ray=RayTarget(address, str(tla), cfg_path))
    return _outcome(one), _outcome(sharded)


@pytest.mark.parametrize("name", sorted(load_expected(CORPUS)))
def test_ray_shards_give_the_single_worker_result_on_corpus_spec(pooled: str, name: str) -> None:
    # SYMMETRY, VIEW, CONSTRAINT, deadlock, violations at depth: as the two-process search.
    # A spec with liveness properties is refused: they need the whole graph in one process.
    tla = CORPUS / f"{name}.tla"
    if load_model(str(tla)).liveness:
        with pytest.raises(UsageError, match="liveness checking needs the whole state graph"):
            _both(pooled, tla)
        return
    one, sharded = _both(pooled, tla)
    assert sharded == one


@pytest.mark.parametrize("name", ["DomainError", "InvariantErrorInInit", "TypeMismatch"])
def test_ray_shards_report_the_single_worker_evaluation_error(pooled: str, name: str) -> None:
    one, sharded = _both(pooled, ERRORS / f"{name}.tla")
    assert one[0] == "error" and sharded == one


def test_ray_shards_give_the_single_worker_counterexample_on_the_flat_press(pooled: str) -> None:
    # The defective reference: its INV_PRESS counterexample, step by step (Protection's
    # counts against TLC's: test_ray_cli_counts_and_usage_errors).
    one, sharded = _both(pooled, REPO / "models" / "HydraulicPressFlat.tla")
    assert one[0] == "safety failure" and sharded == one


def _wide(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[Path, Path, tuple]:
    """A spec of many small levels, its cfg, its single-worker outcome; a progress line per level."""
    tla, cfg = tmp_path / "Wide.tla", tmp_path / "Wide.cfg"
    tla.write_text(WIDE)
    cfg.write_text("INIT Init\nNEXT Next\n")
    monkeypatch.setattr(explore, "PROGRESS_SECONDS", 0.0)
    return tla, cfg, _outcome(explore_states(load_model(str(tla)), workers=1))


def test_ray_a_worker_killed_mid_run_still_gives_the_single_worker_result(
        own_actors: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capfd: pytest.CaptureFixture[str]) -> None:
    tla, cfg, one = _wide(tmp_path, monkeypatch)
    made = _remember_explorers(monkeypatch)
    killed: list[int] = []
    r = explore_states(load_model(str(tla)), workers=2, progress=_kill_at_level(5, made, killed),
                       ray=RayTarget(own_actors, str(tla), str(cfg)))
    assert killed, "the search ended before the kill"
    assert _outcome(r) == one
    assert "searching again with one worker" in capfd.readouterr().err


def _kill_at_level(level: int, made: list, killed: list[int]) -> Callable[[str], None]:
    def progress(line: str) -> None:  # at the end of `level`, SIGKILL the second worker once
        if not killed and line.startswith(f"Progress({level})") and made and made[0].worker_pids:
            killed.append(made[0].worker_pids[1])
            os.kill(killed[0], signal.SIGKILL)
    return progress


def test_ray_a_killed_worker_is_replaced_from_the_last_checkpoint(
        own_actors: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capfd: pytest.CaptureFixture[str]) -> None:
    tla, cfg, one = _wide(tmp_path, monkeypatch)
    made = _remember_explorers(monkeypatch)
    killed: list[int] = []
    target = RayTarget(own_actors, str(tla), str(cfg), str(tmp_path / "ckpt"), 0.0)
    (tmp_path / "ckpt").mkdir()
    r = explore_states(load_model(str(tla)), workers=2, progress=_kill_at_level(5, made, killed), ray=target)
    assert killed and _outcome(r) == one
    err = capfd.readouterr().err
    assert "new workers go on from the checkpoint of level" in err and "with one worker" not in err


def test_ray_a_stopped_search_resumes_from_its_checkpoint(
        own_actors: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    tla, cfg, one = _wide(tmp_path, monkeypatch)
    (tmp_path / "ckpt").mkdir()

    def stop(line: str) -> None:  # the whole search stopped at the end of level 8
        if line.startswith("Progress(8)"):
            raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        explore_states(load_model(str(tla)), workers=2, progress=stop,
                       ray=RayTarget(own_actors, str(tla), str(cfg), str(tmp_path / "ckpt"), 0.0))
    assert json.loads((tmp_path / "ckpt" / "search.json").read_text())["depth"] >= 7
    resumed = explore_states(load_model(str(tla)), workers=2,
                             ray=RayTarget(own_actors, str(tla), str(cfg), str(tmp_path / "ckpt"), 0.0, resume=True))
    assert _outcome(resumed) == one
    with pytest.raises(UsageError, match="no checkpoint of this model"):  # another --workers
        explore_states(load_model(str(tla)), workers=1,
                       ray=RayTarget(own_actors, str(tla), str(cfg), str(tmp_path / "ckpt"), 0.0, resume=True))


def _remember_explorers(monkeypatch: pytest.MonkeyPatch) -> list:
    from safestate.distributed import ray_search
    made: list[ray_search.RayExplorer] = []
    real_init = ray_search.RayExplorer.__init__

    def remember(self: ray_search.RayExplorer, *a: object, **k: object) -> None:
        real_init(self, *a, **k)  # type: ignore[arg-type]
        made.append(self)
    monkeypatch.setattr(ray_search.RayExplorer, "__init__", remember)
    return made


def test_ray_cli_counts_and_usage_errors(own_actors: str) -> None:
    r = run_safestate("check", "models/Protection.tla", "--ray", own_actors, "--workers", "2", "--json", cwd=REPO)
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert (j["distinct_states"], j["states_generated"], j["depth"]) == (1120, 322561, 4)
    assert j["parallel"]["workers"] == 2 and len(j["parallel"]["worker_cpu_seconds"]) == 2
    bad = run_safestate("check", "models/Protection.tla", "--ray", "127.0.0.1:1", cwd=REPO)
    assert bad.returncode == 2 and "no Ray cluster answers there" in bad.stderr
    native = run_safestate("check", "models/Protection.tla", "--ray", own_actors, "--engine", "native", cwd=REPO)
    assert native.returncode == 2 and "--engine native" in native.stderr
    many = run_safestate("check", "models/Protection.tla", "--ray", own_actors, "--workers", "3", cwd=REPO)
    assert many.returncode == 2 and "needs one per worker" in many.stderr
    alone = run_safestate("check", "models/Protection.tla", "--checkpoint", "build/ckpt", cwd=REPO)
    assert alone.returncode == 2 and "give --ray too" in alone.stderr
