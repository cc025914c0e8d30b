"""Issue 16, design §11: the operator link (bridge) from a client's point of view.

Access control in the Safety service's vocabulary, the command round trip through the
SPSC queue, link loss stopping a jog (row C26), bad input and load. Every frame from the
bridge is validated against docs/operator-link-schema.json (tests/python/link_client.py).
No timing is asserted: "eventually" waits are bounded only to fail instead of hanging.
"""

from __future__ import annotations

import json
import socket
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import urlparse

import pytest
import websocket

from safestate.panel.server import DEFAULT_BUILD, PanelError, PanelServer, RunningLink

from link_client import LinkClient

pytestmark = pytest.mark.skipif(not (DEFAULT_BUILD / "safestate_link").is_file(),
                                reason="build/cpp/safestate_link not built (bash scripts/setup.sh)")


@pytest.fixture
def link() -> Iterator[RunningLink]:
    with PanelServer(diagram=False) as running:
        yield running


@pytest.fixture
def operator(link: RunningLink) -> Iterator[LinkClient]:
    # A fixed 8 KB receive buffer: when the controller stops reading, its answers back up
    # in the bridge after a few hundred instead of disappearing into a kernel buffer that
    # the machine may grow to megabytes (the flooding test then saw no `busy` at all).
    c = LinkClient(link.ws_url, receive_buffer=8192)
    assert c.claim(link.token)["type"] == "confirm_control"
    yield c
    c.close()


class Heartbeats:
    """Sends the controlling client's heartbeat every 50 ms until stopped."""

    def __init__(self, client: LinkClient) -> None:
        self.client = client
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        while not self.stop.wait(0.05):
            try:
                self.client.heartbeat()
            except (OSError, websocket.WebSocketException):
                return

    def halt(self) -> None:
        self.stop.set()
        self.thread.join()


def jogging(op: LinkClient) -> Heartbeats:
    """T1 session, jog axis 2 at 400 mm/s requested; heartbeats running."""
    beats = Heartbeats(op)
    assert op.plant(selector="T1", enabling="MIDDLE")["type"] == "plant_set"
    op.status(lambda s: s["selector"] == "T1")
    assert op.command("SERVO_ON")["result"] == "ACCEPTED"
    op.status(lambda s: s["state"] == "MANUAL_IDLE")
    assert op.command("JOG_START", axis=2, direction=1, speed_mm_s=400)["result"] == "ACCEPTED"
    st = op.status(lambda s: s["state"] == "MANUAL_JOGGING")
    assert st["outputs"]["commanded_speed_mm_s"] == 250  # T1 clamp (K29)
    return beats


def test_the_bridge_listens_on_the_loopback_interface_only(link: RunningLink) -> None:
    assert urlparse(link.url).hostname == "127.0.0.1"
    port = urlparse(link.url).port
    out = subprocess.run(["ss", "-ltnH", f"sport = :{port}"], capture_output=True, text=True, check=False).stdout
    if out.strip():  # ss is in iproute2; without it the URL check above stands alone
        local_addresses = {line.split()[3] for line in out.splitlines()}  # State Recv-Q Send-Q Local Peer
        assert local_addresses == {f"127.0.0.1:{port}"}, out


def test_one_controlling_client_observers_refused_and_counted(link: RunningLink, operator: LinkClient) -> None:
    second = LinkClient(link.ws_url)
    refused = second.claim(link.token)
    assert (refused["type"], refused["reason"]) == ("refused", "CONTROL_HELD_BY_OTHER")
    answer = second.command("RESET")
    assert (answer["type"], answer["reason"]) == ("refused", "NO_CONTROL")
    answer = second.plant(estop_pressed=True)
    assert (answer["type"], answer["reason"]) == ("refused", "NO_CONTROL")
    third = LinkClient(link.ws_url)
    assert third.claim("not-the-token")["reason"] == "BAD_TOKEN"
    counters = second.status(lambda s: s["link"]["control_refused"] == 2)["link"]
    assert counters["observer_commands_refused"] == 2
    assert counters["controller_id"] == operator.hello["client_id"]
    # The controller's commands reach the cycle and are answered after it popped them.
    assert operator.command("RESET")["result"] == "WRONG_STATE"  # IDLE: nothing to reset
    # Released control can be claimed by the next client.
    operator.send({"type": "release_control"})
    operator.until(lambda m: m["type"] == "control_released")
    assert second.claim(link.token)["type"] == "confirm_control"


def test_a_world_readable_token_file_is_refused(tmp_path: Path) -> None:
    token = tmp_path / "operator.token"
    token.write_text("secret\n")
    token.chmod(0o644)
    with pytest.raises(PanelError, match=r"mode 0644.*0600"):
        with PanelServer(diagram=False, token_file=token):
            pass
    done = subprocess.run([sys.executable, "-m", "safestate.cli", "panel", "--port", "0", "--token-file", str(token)],
                          capture_output=True, text=True, timeout=60, check=False)
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1 and "readable by others" in done.stderr


def test_bad_input_gets_a_clear_error_and_a_counter(link: RunningLink) -> None:
    c = LinkClient(link.ws_url)
    c.ws.send("{not json")
    assert c.until(lambda m: m["type"] == "error")["error"] == "MALFORMED_JSON"
    c.ws.send("[1, 2]")
    assert c.until(lambda m: m["type"] == "error")["error"] == "MALFORMED_JSON"
    c.ws.send(json.dumps({"v": 1, "id": 5, "type": "teleport"}))
    m = c.answer(5)
    assert m["error"] == "UNKNOWN_TYPE" and "teleport" in m["detail"]
    c.ws.send(json.dumps({"v": 1, "id": 6, "type": "command", "command": "JOG_START", "axis": 1}))
    assert c.answer(6)["error"] == "BAD_FIELD"
    c.ws.send(json.dumps({"v": 2, "id": 7, "type": "heartbeat"}))
    assert c.answer(7)["error"] == "UNSUPPORTED_VERSION"
    counters = c.status(lambda s: s["link"]["bad_field"] >= 2)["link"]
    assert (counters["malformed_json"], counters["unknown_type"]) == (2, 1)


def test_an_oversized_frame_closes_the_connection_with_1009(link: RunningLink) -> None:
    big = LinkClient(link.ws_url)
    limit = big.hello["max_frame_bytes"]
    big.ws.send(json.dumps({"type": "heartbeat", "pad": "x" * limit}))
    with pytest.raises((websocket.WebSocketConnectionClosedException, OSError)):
        for _ in range(100):
            frame = big.ws.recv_data_frame(True)[1]
            if frame.opcode == websocket.ABNF.OPCODE_CLOSE:
                assert int.from_bytes(frame.data[:2], "big") == 1009
                raise websocket.WebSocketConnectionClosedException("closed")
    watcher = LinkClient(link.ws_url)
    assert watcher.status(lambda s: s["link"]["frame_too_large"] == 1)


@pytest.mark.parametrize("how", ["hung", "closed"])
def test_losing_the_controlling_client_stops_a_jog_cat2_and_nothing_else(link: RunningLink, operator: LinkClient,
                                                                         how: str) -> None:
    beats = jogging(operator)
    watcher = LinkClient(link.ws_url)
    before = watcher.status(lambda s: s["state"] == "MANUAL_JOGGING")
    beats.halt()  # hung: socket open, silent
    if how == "closed":
        operator.close()
    st = watcher.status(lambda s: s["state"] in ("STOPPING", "HOLD"))
    stops = [t for t in st["recent_transitions"] if t["cycle"] > before["cycle"]]
    assert stops[0] == dict(stops[0], row="C26", **{"from": "MANUAL_JOGGING", "to": "STOPPING"}), stops
    assert st["stop_category"] == "CAT2"
    assert st["outputs"]["commanded_speed_mm_s"] == 0
    assert st["outputs"]["contactor_closed"] and st["outputs"]["drive_enable"]  # Cat 2: power kept
    assert (st["session_mode"], st["fault_code"]) == (before["session_mode"], "NONE")
    assert not st["operator_link_ok"]
    assert watcher.status(lambda s: s["state"] == "HOLD")["fault_code"] == "NONE"


# Timing-dependent, not strict (session 8).  With its receive buffer full (the fixed 8 KB,
# so that its answers back up in the bridge and `busy` appears), the controller's socket
# drops the bridge's segments, and with them the acknowledgements of its own data: `ss -tni`
# during a failing run showed the controller's flood and heartbeats unsent (notsent 117 KB),
# "lost" segments and a retransmission timer backed off to 816 ms with cwnd 1, so its
# heartbeats reached the bridge more than a second late in about 1 run in 5, and the lease
# expired.  The bridge read everything it received (its receive queue was empty).  Without
# the fixed buffer the kernel absorbed every answer and no `busy` appeared (2 of 4 runs).
@pytest.mark.xfail(strict=False, raises=AssertionError,
                   reason="TCP retransmission backoff on the non-reading controller's full socket can delay its "
                          "heartbeats past the 1 s lease (~1 run in 5)")
def test_a_flooding_controller_keeps_control_while_it_heartbeats_and_excess_requests_get_busy(
        link: RunningLink, operator: LinkClient) -> None:
    """Issue 16 (b): heartbeats never wait behind the controller's own requests.

    The controller sends 3,000 requests without reading a single answer while a thread
    heartbeats: its answers pile up, yet the bridge keeps reading it, so every heartbeat
    arrives and control (and operator_link_ok) outlasts the 1 s lease. Each request is
    answered: by its result, or counted in a `busy` frame once the client reads.  (10,000
    before session 8; with the fixed receive buffer 3,000 still back the answers up, and
    the TCP backoff described above showed up more often with 10,000.)
    """
    n = 3_000
    operator.ws.sock.settimeout(30)  # a bridge that stopped reading would block the send: fail, not hang
    watcher = LinkClient(link.ws_url)
    beats = Heartbeats(operator)
    frame = json.dumps({"v": 1, "type": "command", "command": "PAUSE"})
    for _ in range(n):
        operator.ws.send(frame)
    flooded = watcher.status(lambda s: s["link"]["busy"] > 0)
    # Two leases (2,000 cycles of 1 ms) later, still not having read anything: still in control.
    later = watcher.status(lambda s, c=flooded["cycle"]: s["cycle"] > c + 2_000, timeout=30)
    assert later["link"]["heartbeats"] > flooded["link"]["heartbeats"]
    assert later["link"]["controller_id"] == operator.hello["client_id"]
    assert later["link"]["control_lease_expired"] == 0
    assert later["operator_link_ok"]
    beats.halt()

    results: list[str] = []
    busy = 0
    while len(results) + busy < n:  # not validated frame by frame: the schema check would be the bottleneck
        m = json.loads(operator.ws.recv())
        assert m["type"] != "control_released", m
        if m["type"] == "result":
            results.append(m["result"])
        elif m["type"] == "busy":
            busy += m["dropped"]
    assert busy > 0 and len(results) + busy == n
    assert set(results) <= {"WRONG_STATE", "QUEUE_FULL"}  # PAUSE in IDLE; the queue holds 8
    counters = operator.status(lambda s: s["link"]["busy"] == busy)["link"]
    assert counters["queue_full"] == results.count("QUEUE_FULL")
    assert counters["slow_consumers_closed"] == 0
    assert operator.command("RESET")["result"] == "WRONG_STATE"  # still the controller


def test_a_hundred_observers_receive_the_status_broadcast(link: RunningLink) -> None:
    observers = [LinkClient(link.ws_url) for _ in range(100)]
    cycles = [o.status()["cycle"] for o in observers]
    later = [o.status(lambda s, c=c: s["cycle"] > c)["cycle"] for o, c in zip(observers, cycles)]
    assert all(b > a for a, b in zip(cycles, later))
    assert observers[0].status(lambda s: s["link"]["clients"] == 100)["link"]["status_frames_dropped"] == 0
    for o in observers:
        o.close()


def test_a_client_that_never_reads_is_bounded_and_others_are_served(link: RunningLink) -> None:
    silent = websocket.create_connection(link.ws_url, sockopt=((socket.SOL_SOCKET, socket.SO_RCVBUF, 4096),))
    watcher = LinkClient(link.ws_url)
    st = watcher.status(lambda s: s["link"]["status_frames_dropped"] > 0, timeout=60)
    assert st["link"]["clients"] == 2
    # A client that floods requests without reading: once its replies pile up the bridge
    # stops reading from it (its requests wait in TCP), so its memory stays bounded.
    flood = websocket.create_connection(link.ws_url, sockopt=((socket.SOL_SOCKET, socket.SO_RCVBUF, 4096),))
    flood.sock.settimeout(2)
    try:
        for _ in range(20_000):
            flood.send("{bad")
    except (OSError, websocket.WebSocketException):
        pass  # the send blocked: the bridge no longer reads this client
    st = watcher.status(lambda s: s["link"]["reads_paused"] >= 1, timeout=60)
    assert 0 < st["link"]["malformed_json"] < 20_000
    later = watcher.status(lambda s, c=st["cycle"]: s["cycle"] > c)
    assert later["cycle"] > st["cycle"]
    silent.close()
