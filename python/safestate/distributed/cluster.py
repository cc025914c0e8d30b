"""Reaching a Ray cluster: `--ray local` starts one on this machine for the run (its node
address the loopback; Ray still binds some ports to the machine's address, so token
authentication is what keeps other senders out: docs/distributed.md); `--ray HOST:PORT` joins a running one (`ray start --head` there; the
token Ray's authentication writes must be on this machine too).  A process that is
already connected (a test's fixture) keeps its connection.

Every worker hashes with the same string-hash seed (PYTHONHASHSEED in the job's
runtime environment): the owner of a state is its hash modulo the number of shards,
and every shard must agree on it.
"""

from __future__ import annotations

import socket
from typing import Any

from ..errors import UsageError

HASH_SEED = "0"
REACH_SECONDS = 5.0


def ray_module() -> Any:
    try:
        import ray
    except ImportError:
        raise UsageError("--ray needs Ray: pip install 'ray>=2.52' (it is in the test dependencies)") from None
    return ray


def runtime_env() -> dict[str, Any]:
    return {"env_vars": {"PYTHONHASHSEED": HASH_SEED}}


def connect(address: str, workers: int) -> tuple[Any, bool]:
    """(ray, whether this call connected it: the caller then shuts it down)."""
    ray = ray_module()
    if ray.is_initialized():
        return ray, False
    kwargs: dict[str, Any] = dict(runtime_env=runtime_env(), include_dashboard=False, log_to_driver=False,
                                  configure_logging=False)
    if address == "local":
        ray.init(num_cpus=workers, _node_ip_address="127.0.0.1", **kwargs)
        return ray, True
    _reachable(address)
    try:
        ray.init(address=address, **kwargs)
    except (ConnectionError, RuntimeError, ValueError) as e:
        raise UsageError(f"--ray {address}: cannot join the Ray cluster ({one_line(e)})") from None
    return ray, True


def _reachable(address: str) -> None:
    """A clear error at once for an address nobody listens on (Ray itself retries for minutes)."""
    host, sep, port = address.rpartition(":")
    if not sep or not port.isdigit():
        raise UsageError(f"--ray {address}: expected 'local' or HOST:PORT of a running cluster's head "
                         f"(`ray start --head` prints it)")
    try:
        with socket.create_connection((host, int(port)), timeout=REACH_SECONDS):
            pass
    except OSError as e:
        raise UsageError(f"--ray {address}: no Ray cluster answers there ({e.strerror or e})") from None


def one_line(e: BaseException) -> str:
    text = str(e).strip().splitlines()
    return text[0] if text else type(e).__name__
