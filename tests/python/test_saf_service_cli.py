"""Issue 30 part B (docs/design/safety-service.md §14, §15): the Set Estop extension, the
sealed subsystem link and their HMAC agree between the C++ (safestate._saf_net) and the simulators' Python wire format
(written from the design page, with Python's hmac); `safestate saf` fails with one line
and exit code 2 on a missing configuration and on a port that is taken."""

from __future__ import annotations

import hashlib
import hmac
import random
import socket
import subprocess
import sys
from pathlib import Path

import pytest

from saf_processes import write_config

_saf_net = pytest.importorskip("safestate._saf_net", reason="binding not built (bash scripts/setup.sh)")
from safestate.saf_service import wire  # noqa: E402

pytestmark = pytest.mark.req("SAF-03")


def test_cpp_and_python_set_estop_extension_are_byte_identical() -> None:
    rng = random.Random(30)
    for _ in range(200):
        emergency = rng.random() < 0.5
        client, sequence = rng.randrange(1 << 32), rng.randrange(1 << 64)
        key = bytes(rng.randrange(256) for _ in range(rng.randrange(16, 65))) if rng.random() < 0.7 else None
        assert _saf_net.encode_set_estop(emergency, client, sequence, key) == wire.set_estop(
            emergency, client, sequence, key)


def test_cpp_hmac_sha256_equals_pythons_on_random_keys_and_messages() -> None:
    rng = random.Random(4231)
    for _ in range(200):
        key = bytes(rng.randrange(256) for _ in range(rng.randrange(0, 200)))
        data = bytes(rng.randrange(256) for _ in range(rng.randrange(0, 300)))
        assert _saf_net.hmac_sha256(key, data) == hmac.new(key, data, hashlib.sha256).digest()


def test_cpp_and_python_sealed_link_messages_are_byte_identical_and_open() -> None:
    """The link's sealed form (design §15.2) from the C++ (the service's end) and from
    Python (the simulator's end) agree, and Python's open gives the seed form back."""
    rng = random.Random(152)
    seeds = [wire.report_health("ERROR"), wire.confirm_control(wire.CONTROL_ACCEPTED), wire.report_control(7, 225),
             wire.report_subsystem_state("EMERGENCY"), wire.message(wire.QUERY_CONTROL),
             wire.message(wire.SET_SUBSYSTEM_STATE, bytes([1])),
             wire.message(wire.REQUEST_CONTROL, bytes([0, 225, 3, 2, 1, 0]))]
    for _ in range(100):
        seed = rng.choice(seeds)
        key = bytes(rng.randrange(256) for _ in range(rng.randrange(16, 65)))
        sequence = rng.randrange(1 << 64)
        to_subsystem = rng.random() < 0.5
        direction = wire.TO_SUBSYSTEM if to_subsystem else wire.TO_SERVICE
        sealed = _saf_net.link_seal(seed, sequence, to_subsystem, key)
        assert sealed == wire.seal(seed, sequence, direction, key)
        assert wire.open_sealed(sealed, direction, key, wire.LinkReceiver()) == ("OK", seed)
        other = wire.TO_SERVICE if to_subsystem else wire.TO_SUBSYSTEM
        assert wire.open_sealed(sealed, other, key, wire.LinkReceiver())[0] == "BAD_MAC"
        assert wire.open_sealed(seed, direction, key, wire.LinkReceiver())[0] == "UNAUTHENTICATED"


def _saf(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "safestate.cli", "saf", *args], capture_output=True, text=True,
                          timeout=60)


def test_missing_configuration_is_one_line_and_exit_2(tmp_path: Path) -> None:
    for role in ("serve", "client", "subsystem"):
        r = _saf(role, "--config", str(tmp_path / "absent.toml"))
        assert r.returncode == 2
        assert r.stderr.count("\n") == 1 and "absent.toml: cannot read the configuration" in r.stderr


def test_port_already_taken_is_one_line_and_exit_2(tmp_path: Path) -> None:
    config, ports = write_config(tmp_path, key=False)
    squatter = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    squatter.bind(("127.0.0.1", ports["service"]))
    try:
        r = _saf("serve", "--config", str(config), "--cycles", "1")
    finally:
        squatter.close()
    assert r.returncode == 2
    assert "cannot bind the Safety Client port" in r.stderr and "Traceback" not in r.stderr
