"""Issue 30 part B, item 2 (docs/design/safety-service.md §14): the Safety service, the
Safety Client and the subsystem as three processes on 127.0.0.1 (`safestate saf serve |
client | subsystem`), with HMAC-SHA256 and sequence numbers on. The scenario a user would
run: press, clear, the client falls silent (timeout), a spoofed clear from another port
while pressed, a byte-identical replay of a captured clear from the dead client's own
port, a flood while clear, and the service killed. The measured end-to-end E-stop latency
and timeout reaction are printed (never a pass/fail bound)."""

from __future__ import annotations

import signal
import socket
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from saf_processes import CLIENT_ID, Event, Process, write_config

_saf_net = pytest.importorskip("safestate._saf_net", reason="binding not built (bash scripts/setup.sh)")

pytestmark = pytest.mark.req("SAF-02", "SAF-03")


def is_state(after: str) -> object:
    return lambda e: e.get("event") == "state" and e.get("after") == after


def rejected(p: Process, reason: str, since: float) -> int:
    return sum(1 for e in p.snapshot() if e.get("event") == "rejected" and e.get("reason") == reason and e["t"] >= since)


def subsystem_states_between(sub: Process, t0: float, t1: float) -> list[str]:
    return [e["after"] for e in sub.state_events(t0, t1)]


@pytest.fixture()
def three(tmp_path: Path) -> Iterator[tuple[Process, Process, Process, dict[str, int], Path]]:
    config, ports = write_config(tmp_path)
    sub = Process("subsystem", config)
    svc = Process("serve", config)
    cli = Process("client", config, "--mode", "clear")
    procs = [cli, svc, sub]
    try:
        yield sub, svc, cli, ports, config
    finally:
        for p in procs:
            p.stop()


def test_three_processes_press_clear_timeout_spoof_replay_flood_kill(three) -> None:
    sub, svc, cli, ports, config = three
    report: list[str] = []
    svc.wait_for(is_state("OPERATIONAL"))
    t_ready = time.monotonic()
    time.sleep(0.3)
    assert sub.state_events(0.0) == [] or sub.state_events(0.0)[-1]["after"] == "OPERATIONAL"

    # Press: the subsystem reaches EMERGENCY; latency from the first SET datagram sent.
    cli.send("set")
    pressed = cli.wait_for(lambda e: e.get("event") == "mode" and e.get("mode") == "set", after=t_ready)
    emergency = sub.wait_for(is_state("EMERGENCY"), after=pressed["t"])
    svc_emergency = svc.wait_for(is_state("EMERGENCY"), after=pressed["t"])
    report.append(f"press: service EMERGENCY after {1000 * (svc_emergency['t'] - pressed['t']):.0f} ms, "
                  f"subsystem EMERGENCY after {1000 * (emergency['t'] - pressed['t']):.0f} ms (end to end)")

    # Clear: back to OPERATIONAL; the clear datagram is captured for the replay below.
    cli.send("clear")
    cleared = cli.wait_for(lambda e: e.get("event") == "mode" and e.get("mode") == "clear", after=pressed["t"])
    captured_clear = bytes.fromhex(cleared["datagram"])
    sub.wait_for(is_state("OPERATIONAL"), after=cleared["t"])

    # Timeout: the client falls silent; the E-stop times out (ESTOPTIMEOUT) and the subsystem follows.
    cli.send("silent")
    silent = cli.wait_for(lambda e: e.get("event") == "mode" and e.get("mode") == "silent", after=cleared["t"])
    svc_timeout = svc.wait_for(is_state("EMERGENCY"), after=silent["t"])
    sub_timeout = sub.wait_for(is_state("EMERGENCY"), after=silent["t"])
    # `silent` carries the time of the last Set Estop sent (its cycle may have run late).
    last_sent = silent["last_sent"]
    report.append(f"timeout: after the last Set Estop, service EMERGENCY (row {svc_timeout['row']}) after "
                  f"{1000 * (svc_timeout['t'] - last_sent):.0f} ms, subsystem EMERGENCY after "
                  f"{1000 * (sub_timeout['t'] - last_sent):.0f} ms (ESTOPTIMEOUT 100 ms, CYCLEINTERVAL 50 ms)")
    cli.send("clear")
    sub.wait_for(is_state("OPERATIONAL"), after=sub_timeout["t"])

    # Spoof: pressed, while another local process sends clears from its own port (the seed's
    # form, the extension without MAC, and the captured authentic clear).
    cli.send("set")
    t_set = cli.wait_for(lambda e: e.get("event") == "mode" and e.get("mode") == "set", after=sub_timeout["t"])["t"]
    sub.wait_for(is_state("EMERGENCY"), after=t_set)
    attacker = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    attacker.bind(("127.0.0.1", 0))
    from safestate.saf_service import wire

    t_spoof = time.monotonic()
    for _ in range(20):
        for d in (wire.set_estop_seed(False), wire.set_estop(False, CLIENT_ID, 1 << 60, None), captured_clear):
            attacker.sendto(d, ("127.0.0.1", ports["service"]))
        time.sleep(0.05)
    time.sleep(0.2)
    t_spoof_end = time.monotonic()
    assert subsystem_states_between(sub, t_spoof, t_spoof_end) == [], "a spoofed clear released the E-stop"
    assert rejected(svc, "ESTOP_WRONG_SOURCE", t_spoof) >= 60
    report.append(f"spoof: {rejected(svc, 'ESTOP_WRONG_SOURCE', t_spoof)} forged clears rejected "
                  "(ESTOP_WRONG_SOURCE), subsystem EMERGENCY throughout")

    # Replay with the real client dead: its port is free, the captured clear sent from it.
    cli.stop(signal.SIGKILL)
    replayer = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    replayer.bind(("127.0.0.1", ports["client"]))
    t_replay = time.monotonic()
    for _ in range(40):
        replayer.sendto(captured_clear, ("127.0.0.1", ports["service"]))
        replayer.sendto(wire.set_estop(False, CLIENT_ID, 1 << 60, b"\x01" * 32), ("127.0.0.1", ports["service"]))
        time.sleep(0.05)
    time.sleep(0.2)
    t_replay_end = time.monotonic()
    replayer.close()
    assert subsystem_states_between(sub, t_replay, t_replay_end) == [], "a replayed clear released the E-stop"
    assert rejected(svc, "ESTOP_REPLAY", t_replay) >= 40
    assert rejected(svc, "ESTOP_BAD_MAC", t_replay) >= 40
    report.append(f"replay (client dead): {rejected(svc, 'ESTOP_REPLAY', t_replay)} replays (ESTOP_REPLAY) and "
                  f"{rejected(svc, 'ESTOP_BAD_MAC', t_replay)} forged MACs rejected, subsystem EMERGENCY throughout")

    # A restarted client (its sequence starts from the wall clock) is accepted again.
    cli2 = Process("client", config, "--mode", "clear")
    try:
        sub.wait_for(is_state("OPERATIONAL"), after=t_replay_end)
        # Flood while clear: a burst of 3,000 and a second of sustained sending.
        t_flood = time.monotonic()
        garbage = wire.set_estop(False, CLIENT_ID, 1, None)
        for _ in range(3000):
            attacker.sendto(garbage, ("127.0.0.1", ports["service"]))
        end = time.monotonic() + 1.0
        while time.monotonic() < end:
            for _ in range(200):
                attacker.sendto(garbage, ("127.0.0.1", ports["service"]))
            time.sleep(0.01)
        flood_emergency = sub.wait_for(is_state("EMERGENCY"), after=t_flood)
        drops = sum(e["count"] for e in svc.snapshot() if e.get("event") == "dropped" and e["t"] >= t_flood)
        overflow_clears = rejected(svc, "ESTOP_CLEAR_IN_OVERFLOW", t_flood)
        assert drops > 0, "kernel drops not counted"
        report.append(f"flood: subsystem EMERGENCY {1000 * (flood_emergency['t'] - t_flood):.0f} ms after it began, "
                      f"{drops} kernel drops counted, {overflow_clears} clears read during the overflow rejected")
        recovered = sub.wait_for(is_state("OPERATIONAL"), after=flood_emergency["t"], deadline_s=20)
        report.append(f"flood: OPERATIONAL again {1000 * (recovered['t'] - end):.0f} ms after it ended")

        # Kill the service: the subsystem notices the silence and goes to EMERGENCY by itself.
        t_kill = time.monotonic()
        svc.stop(signal.SIGKILL)
        silent_event = sub.wait_for(lambda e: e.get("event") == "service-silent", after=t_kill)
        dead = sub.wait_for(is_state("EMERGENCY"), after=t_kill)
        assert dead["why"] == "the Safety service is silent"
        report.append(f"service killed: subsystem EMERGENCY after {1000 * (dead['t'] - t_kill):.0f} ms "
                      f"(service_timeout 1.0 s; silence seen {silent_event['silence']:.2f} s)")
    finally:
        cli2.stop()
        attacker.close()
    print("\n" + "\n".join(f"  {line}" for line in report))


def _first_event(p: Process, name: str) -> Event:
    return p.wait_for(lambda e: e.get("event") == name)


def test_serve_stops_cleanly_on_sigterm_and_reports_its_counters(tmp_path: Path) -> None:
    config, _ = write_config(tmp_path, key=False)
    svc = Process("serve", config)
    _first_event(svc, "started")
    assert svc.stop(signal.SIGTERM) == 0
    stopped = _first_event(svc, "stopped")
    assert stopped["state"] in ("PAIRING", "EMERGENCY")  # no client: never OPERATIONAL
    assert stopped["cycles"] > 0 and "rejected" in stopped and "kernel_dropped" in stopped


def test_key_file_readable_by_others_is_refused(tmp_path: Path) -> None:
    config, _ = write_config(tmp_path, key=True)
    (tmp_path / "saf.key").chmod(0o644)
    svc = Process("serve", config)
    svc.proc.wait(timeout=20)
    rc = svc.proc.returncode
    err = svc.proc.stderr.read() if svc.proc.stderr else ""
    assert rc == 2
    assert "saf.key" in err and "0644" in err and "0600" in err
    assert "Traceback" not in err


@pytest.mark.parametrize(("edit", "expected"), [
    (("ESTOPTIMEOUT = 0.1", "ESTOPTIMEOUT = -1"), "[parameters] ESTOPTIMEOUT: expected a positive number of seconds"),
    (("replay_window = 64", "replay_window = 0"), "[security] replay_window: expected a whole number"),
    (("\nport = ", "\nport = 70000 #"), "[client] port: expected a UDP port"),
])
def test_bad_configuration_names_file_line_and_expectation(tmp_path: Path, edit: tuple[str, str], expected: str) -> None:
    config, _ = write_config(tmp_path, key=False)
    text = config.read_text(encoding="utf-8")
    config.write_text(text.replace(edit[0], edit[1], 1), encoding="utf-8")
    line = next(i + 1 for i, s in enumerate(config.read_text(encoding="utf-8").splitlines()) if edit[1].strip() in s)
    svc = Process("serve", config)
    svc.proc.wait(timeout=20)
    err = svc.proc.stderr.read() if svc.proc.stderr else ""
    assert svc.proc.returncode == 2
    assert f"{config}:{line}: {expected}" in err, err
