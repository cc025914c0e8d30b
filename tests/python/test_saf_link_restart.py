"""Issue 30, what the sender binding left open (docs/design/safety-service.md §15), with the
three processes on 127.0.0.1 (`safestate saf serve | client | subsystem`, key file on):

- the replay window across a restart of the service: a genuine CLEAR captured before the
  service is killed and restarted, replayed from the client's own port after it, is
  rejected as stale (the sequence file), and the subsystem stays EMERGENCY while the
  client holds SET;
- the service <-> subsystem link is authenticated both ways: a process bound to the dead
  service's port cannot release the subsystem (nor feed its watchdog), a process bound to
  the dead subsystem's port cannot report a good health or confirm control.

Deadlines only bound a hang; no test passes or fails on a time."""

from __future__ import annotations

import signal
import socket
import stat
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from saf_processes import KEY_HEX, Process, write_config

_saf_net = pytest.importorskip("safestate._saf_net", reason="binding not built (bash scripts/setup.sh)")

from safestate.saf_service import wire  # noqa: E402

pytestmark = pytest.mark.req("SAF-02", "SAF-03")

KEY = bytes.fromhex(KEY_HEX)


def is_state(after: str) -> object:
    return lambda e: e.get("event") == "state" and e.get("after") == after


def is_mode(mode: str) -> object:
    return lambda e: e.get("event") == "mode" and e.get("mode") == mode


def rejected(p: Process, reason: str, since: float) -> int:
    return sum(1 for e in p.snapshot() if e.get("event") == "rejected" and e.get("reason") == reason and e["t"] >= since)


def states_after(p: Process, since: float) -> list[str]:
    return [e["after"] for e in p.state_events(since)]


def sub_state(sub: Process) -> str:
    states = [e["after"] for e in sub.state_events(0.0)]
    return states[-1] if states else "OPERATIONAL"


def replay(cli: Process, datagram: str, svc: Process, total: int, since: float) -> None:
    """Sends the capture from the client's own port until `total` have been rejected as stale
    since `since` (10 more per call); fails when any is accepted or counted otherwise."""
    for _ in range(10):
        cli.send(f"replay {datagram}")
        time.sleep(0.05)
    deadline = time.monotonic() + 10
    while rejected(svc, "ESTOP_STALE", since) < total and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.2)
    assert rejected(svc, "ESTOP_STALE", since) == total
    assert rejected(svc, "ESTOP_REPLAY", since) == 0


def start(tmp_path: Path, **config: object) -> tuple[Process, Process, Process, dict[str, int], Path]:
    path, ports = write_config(tmp_path, **config)  # type: ignore[arg-type]
    sub = Process("subsystem", path)
    svc = Process("serve", path)
    cli = Process("client", path, "--mode", "clear")
    return sub, svc, cli, ports, path


def test_a_clear_captured_before_a_restart_is_stale_after_it(tmp_path: Path) -> None:
    # Window 1: any sequence below the highest accepted counts as stale, however few Set
    # Estops the client sent between the capture and the restart.
    sub, svc, cli, _, config = start(tmp_path, sequence_file=True, replay_window=1)
    restarted: Process | None = None
    try:
        first = svc.wait_for(lambda e: e.get("event") == "sequences")
        assert first["restored"] is False  # the first start creates the file
        cleared = cli.wait_for(is_mode("clear"))
        captured_clear = cleared["datagram"]  # a genuine, authenticated CLEAR
        svc.wait_for(is_state("OPERATIONAL"))
        cli.send("set")
        pressed = cli.wait_for(is_mode("set"))
        sub_emergency = sub.wait_for(is_state("EMERGENCY"), after=pressed["t"])["t"]
        svc.wait_for(is_state("EMERGENCY"), after=pressed["t"])
        seq = tmp_path / "saf.seq"
        assert stat.S_IMODE(seq.stat().st_mode) == 0o600

        # The client falls silent (pressed, its messages lost) and the service is killed and
        # restarted: the replay is the first Set Estop the new service sees, which a service
        # that forgot the window would accept (PAIRING -> OPERATIONAL, control released).
        cli.send("silent")
        cli.wait_for(is_mode("silent"), after=pressed["t"])
        svc.stop(signal.SIGKILL)
        restarted = Process("serve", config)
        restored = restarted.wait_for(lambda e: e.get("event") == "sequences")
        assert restored["restored"] is True and restored["estop"] is not None
        t_restart = restored["t"]
        time.sleep(0.6)  # a health report has arrived: only the E-stop keeps it from OPERATIONAL
        replay(cli, captured_clear, restarted, 10, t_restart)
        assert "OPERATIONAL" not in states_after(restarted, t_restart), "the replayed clear was accepted"

        # The client holds SET again; the capture is stale all the same.
        cli.send("set")
        t_set = cli.wait_for(is_mode("set"), after=t_restart)["t"]
        restarted.wait_for(is_state("EMERGENCY"), after=t_restart)
        replay(cli, captured_clear, restarted, 20, t_restart)
        assert "OPERATIONAL" not in states_after(restarted, t_restart)
        assert t_set > t_restart
        assert states_after(sub, sub_emergency + 1e-6) == [], "the subsystem left EMERGENCY"
        assert sub_state(sub) == "EMERGENCY"
        # The restarted service's sealed messages are fresh for the subsystem.
        assert rejected(sub, "REPLAY", t_restart) + rejected(sub, "STALE", t_restart) == 0
    finally:
        for p in (cli, restarted, svc, sub):
            if p is not None:
                p.stop()


def test_a_clean_stop_stores_the_last_accepted_sequence(tmp_path: Path) -> None:
    sub, svc, cli, _, _ = start(tmp_path, sequence_file=True)
    try:
        svc.wait_for(is_state("OPERATIONAL"))
        cli.send("quit")
        last = cli.wait_for(lambda e: e.get("event") == "stopped")["last_sequence"]
        svc.wait_for(lambda e: e.get("event") == "state" and e.get("after") == "EMERGENCY")  # timed out: all read
        assert svc.stop(signal.SIGTERM) == 0
        lines = (tmp_path / "saf.seq").read_text(encoding="utf-8").splitlines()
        assert lines[0] == "safestate-saf-sequence 1"
        assert lines[1] == f"estop {last}"
        assert lines[2].startswith("subsystem ") and lines[2] != "subsystem none"
    finally:
        for p in (cli, svc, sub):
            p.stop()


def test_a_corrupt_sequence_file_stops_the_service_with_the_file_and_line(tmp_path: Path) -> None:
    config, _ = write_config(tmp_path, sequence_file=True)
    seq = tmp_path / "saf.seq"
    seq.write_text("safestate-saf-sequence 1\nestop twelve\nsubsystem none\nservice 1\n", encoding="utf-8")
    seq.chmod(0o600)
    svc = Process("serve", config)
    svc.proc.wait(timeout=20)
    err = svc.proc.stderr.read() if svc.proc.stderr else ""
    assert svc.proc.returncode == 2
    assert f"{seq}:2: sequence file: expected 'estop <" in err, err
    assert "Traceback" not in err
    assert seq.read_text(encoding="utf-8").startswith("safestate-saf-sequence 1\nestop twelve")  # not reset


@pytest.mark.parametrize(("value", "expected"), [
    ("5", "[security] sequence_file: expected a path (relative to the configuration file), got 5"),
    ('"no/such/folder/saf.seq"', "saf.seq: sequence file cannot be written (No such file or directory)"),
])
def test_a_bad_sequence_file_setting_is_one_line_and_exit_2(tmp_path: Path, value: str, expected: str) -> None:
    config, _ = write_config(tmp_path, sequence_file=True)
    config.write_text(config.read_text(encoding="utf-8").replace('sequence_file = "saf.seq"',
                                                                 f"sequence_file = {value}"), encoding="utf-8")
    svc = Process("serve", config)
    svc.proc.wait(timeout=20)
    err = svc.proc.stderr.read() if svc.proc.stderr else ""
    assert svc.proc.returncode == 2
    assert expected in err and err.count("\n") == 1, err


Cell = tuple[Process, Process, Process, dict[str, int], socket.socket]


@pytest.fixture
def cell(tmp_path: Path) -> Iterator[Cell]:
    """The three processes on a sealed link with the service OPERATIONAL, and an unbound
    UDP socket for the impostor; everything stopped and closed afterwards."""
    sub, svc, cli, ports, _ = start(tmp_path)
    impostor = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        svc.wait_for(is_state("OPERATIONAL"))
        yield sub, svc, cli, ports, impostor
    finally:
        impostor.close()
        for p in (cli, svc, sub):
            p.stop()


def test_a_process_on_the_dead_services_port_does_not_release_the_subsystem(cell: Cell) -> None:
    sub, svc, cli, ports, impostor = cell
    cli.send("set")
    pressed = cli.wait_for(is_mode("set"))
    sub.wait_for(is_state("EMERGENCY"), after=pressed["t"])
    time.sleep(0.3)  # the subsystem is held by the service, EMERGENCY
    svc.stop(signal.SIGKILL)
    impostor.bind(("127.0.0.1", ports["service_subsystem"]))
    release = wire.message(wire.SET_SUBSYSTEM_STATE, bytes([1]))
    heartbeat = wire.message(wire.QUERY_HEALTH_SUMMARY)
    to = ("127.0.0.1", ports["subsystem"])
    t0 = time.monotonic()
    for _ in range(30):  # 1.5 s: longer than service_timeout
        impostor.sendto(release, to)  # the seed's form
        impostor.sendto(heartbeat, to)
        impostor.sendto(wire.seal(release, 1 << 62, wire.TO_SUBSYSTEM, b"\x07" * 32), to)  # another key
        impostor.sendto(wire.seal(release, 1, wire.TO_SUBSYSTEM, KEY), to)  # the right key, stale
        time.sleep(0.05)
    silent = sub.wait_for(lambda e: e.get("event") == "service-silent", after=t0)
    time.sleep(0.2)
    assert states_after(sub, t0) == [], "the impostor released the subsystem"
    assert rejected(sub, "UNAUTHENTICATED", t0) == 60
    assert rejected(sub, "BAD_MAC", t0) == 30
    assert rejected(sub, "STALE", t0) + rejected(sub, "REPLAY", t0) == 30
    assert silent["t"] > t0  # its heartbeats did not keep the watchdog quiet


def test_a_process_on_the_dead_subsystems_port_is_rejected_and_counted(cell: Cell) -> None:
    sub, svc, _cli, ports, impostor = cell
    sub.send("health ERROR")
    t_error = sub.wait_for(lambda e: e.get("event") == "health")["t"]
    svc.wait_for(is_state("EMERGENCY"), after=t_error)
    sub.stop(signal.SIGKILL)
    impostor.bind(("127.0.0.1", ports["subsystem"]))
    to = ("127.0.0.1", ports["service_subsystem"])
    normal = wire.report_health("NORMAL")
    confirm = wire.confirm_control(wire.CONTROL_ACCEPTED)
    t0 = time.monotonic()
    for _ in range(40):  # 2 s while the client holds CLEAR
        impostor.sendto(normal, to)
        impostor.sendto(confirm, to)
        impostor.sendto(wire.seal(normal, 1 << 62, wire.TO_SERVICE, b"\x07" * 32), to)
        impostor.sendto(wire.seal(normal, 1 << 62, wire.TO_SUBSYSTEM, KEY), to)  # reflected direction
        time.sleep(0.05)
    time.sleep(0.3)
    assert "OPERATIONAL" not in states_after(svc, t0), "a forged health summary released the E-stop"
    assert rejected(svc, "REPORT_UNAUTHENTICATED", t0) == 80
    assert rejected(svc, "REPORT_BAD_MAC", t0) == 80
    names = {e.get("message") for e in svc.snapshot() if e.get("event") == "rejected" and e["t"] >= t0
             and e.get("reason") == "REPORT_UNAUTHENTICATED"}
    assert names == {"REPORT_HEALTH_SUMMARY", "CONFIRM_CONTROL"}, names
