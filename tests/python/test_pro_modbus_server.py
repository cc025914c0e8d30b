"""PRO-05 communications unit: ao_modbus_server (C++, libmodbus) on 127.0.0.1 driven by a
real Modbus TCP client (pymodbus) and by raw frames for the malformed requests. The server
runs as `pro_modbus_serve` (build/cpp) with a fixed process image; the register map is
docs/design/protection.md, "Modbus register map"."""

from __future__ import annotations

import select
import socket
import struct
import subprocess
import time
from collections.abc import Iterator

import pytest

from modbus_server_process import SERVE, ModbusServerProcess

pymodbus_client = pytest.importorskip("pymodbus.client", reason="pymodbus not installed (pip install -e '.[test]')")
pytestmark = pytest.mark.skipif(not SERVE.is_file(), reason="C++ tree not built (bash scripts/setup.sh)")

# The process image pro_modbus_serve serves in these tests, in the controller's units.
IMAGE = {"--temperature-c": -12, "--voltage-dv": 241, "--fan-percent": 100, "--protection-state": 1,
         "--supervisor-state": 2, "--last-clear-result": 2}
IMAGE_OPTIONS = [str(x) for kv in IMAGE.items() for x in kv]
UNIT = 1
NO_REPLY_WAIT_S = 0.3  # a discarded frame: nothing may arrive within this (the tick is 5 ms)


def mbap(pdu: bytes, *, unit: int = UNIT, protocol: int = 0, length: int | None = None, tid: int = 0x4D42) -> bytes:
    """A Modbus TCP frame: MBAP header (length computed unless given) and PDU."""
    return struct.pack(">HHHB", tid, protocol, len(pdu) + 1 if length is None else length, unit) + pdu


def exchange(sock: socket.socket, frame: bytes, wait: float = 2.0) -> bytes | None:
    """Send `frame`; the reply bytes, b"" if the server closed the connection, None if silent."""
    sock.sendall(frame)
    ready, _, _ = select.select([sock], [], [], wait)
    return sock.recv(300) if ready else None


def closed_by_server(sock: socket.socket, wait: float = 5.0) -> bool:
    """True once the server has closed `sock` (EOF, or a reset if unread data was pending)."""
    ready, _, _ = select.select([sock], [], [], wait)
    try:
        return bool(ready) and sock.recv(1) == b""
    except ConnectionResetError:
        return True


@pytest.fixture(scope="module")
def server() -> Iterator[ModbusServerProcess]:
    proc = ModbusServerProcess("--frame-timeout-ticks", "10", *IMAGE_OPTIONS)
    yield proc
    proc.stop()


def client_for(server: ModbusServerProcess) -> pymodbus_client.ModbusTcpClient:
    client = pymodbus_client.ModbusTcpClient("127.0.0.1", port=server.port, timeout=2, retries=0)
    assert client.connect()
    return client


def assert_serves_the_image(server: ModbusServerProcess) -> None:
    client = client_for(server)
    try:
        reply = client.read_input_registers(0, count=6, device_id=UNIT)
        assert not reply.isError(), reply
        assert reply.registers == [(-12) & 0xFFFF, 241, 100, 1, 2, 2]
    finally:
        client.close()


def test_every_input_register_reads_with_its_scaling(server: ModbusServerProcess) -> None:
    client = client_for(server)
    try:
        regs = [client.read_input_registers(a, count=1, device_id=UNIT).registers[0] for a in range(6)]
        temperature = client.convert_from_registers([regs[0]], data_type=client.DATATYPE.INT16)
    finally:
        client.close()
    assert temperature == -12                # register 0: degC, int16 two's complement
    assert regs[1] / 10 == pytest.approx(24.1)  # register 1: supply voltage in 0.1 V
    assert regs[2] == 100                    # register 2: fan command, percent
    assert regs[3] == 1                      # register 3: protection state PROTECTION
    assert regs[4] == 2                      # register 4: supervisor state DEGRADED
    assert regs[5] == 2                      # register 5: last clear request denied


def test_unit_ids_zero_and_ff_are_served_like_the_configured_one(server: ModbusServerProcess) -> None:
    client = client_for(server)
    try:
        for unit in (0, 0xFF):
            assert client.read_input_registers(1, count=1, device_id=unit).registers == [241]
    finally:
        client.close()


def test_coil_write_reaches_the_latch_clear_request_once_per_write() -> None:
    proc = ModbusServerProcess(*IMAGE_OPTIONS)
    try:
        client = client_for(proc)
        assert not client.write_coil(1, True, device_id=UNIT).isError()  # the write enable
        assert not client.write_coil(0, True, device_id=UNIT).isError()
        first = proc.next_line(5.0)
        assert first is not None and first.startswith("clear request taken at tick"), first
        assert not client.write_coil(1, True, device_id=UNIT).isError()
        assert not client.write_coil(0, False, device_id=UNIT).isError()  # 0 requests nothing
        assert not client.write_coil(1, True, device_id=UNIT).isError()
        assert not client.write_coils(0, [True], device_id=UNIT).isError()  # function 0x0F
        second = proc.next_line(5.0)
        assert second is not None and second.startswith("clear request taken at tick"), second
        assert client.read_coils(0, count=1, device_id=UNIT).bits[0] is False  # taken: reads back 0
        client.close()
        assert [line for line in proc.drain() if line.startswith("clear")] == []
    finally:
        proc.stop()


# The malformed or invalid requests, each with the server's answer: ("exception", code) is a
# Modbus exception response with that code, "silent" a discarded frame (no reply, the same
# connection keeps serving), "closed" the server closing the connection (framing lost).
MALFORMED = [
    ("fc 0x07 read exception status (serial only)", mbap(b"\x07"), ("exception", 0x01)),
    ("fc 0x08 diagnostics", mbap(b"\x08\x00\x00\x12\x34"), ("exception", 0x01)),
    ("fc 0x2B read device identification", mbap(b"\x2b\x0e\x01\x00"), ("exception", 0x01)),
    ("fc 0x11 report server id (not offered)", mbap(b"\x11"), ("exception", 0x01)),
    ("fc 0x7F (undefined)", mbap(b"\x7f\x00\x00\x00\x01"), ("exception", 0x01)),
    ("read input registers at address 6 (past the map)", mbap(b"\x04\x00\x06\x00\x01"), ("exception", 0x02)),
    ("read input registers 0..6 (crosses the end)", mbap(b"\x04\x00\x00\x00\x07"), ("exception", 0x02)),
    ("read input registers, quantity 0", mbap(b"\x04\x00\x00\x00\x00"), ("exception", 0x03)),
    ("read input registers, quantity 126 (> 125)", mbap(b"\x04\x00\x00\x00\x7e"), ("exception", 0x03)),
    ("read coil 2 (only coils 0, 1 exist)", mbap(b"\x01\x00\x02\x00\x01"), ("exception", 0x02)),
    ("read coils, quantity 0", mbap(b"\x01\x00\x00\x00\x00"), ("exception", 0x03)),
    ("write single coil 0 with value 0x1234", mbap(b"\x05\x00\x00\x12\x34"), ("exception", 0x03)),
    ("write single coil 2", mbap(b"\x05\x00\x02\xff\x00"), ("exception", 0x02)),
    ("write coil 0 without the write enable", mbap(b"\x05\x00\x00\xff\x00"), ("exception", 0x01)),
    ("write single register 0 (the read-only temperature)", mbap(b"\x06\x00\x00\x00\x2a"), ("exception", 0x02)),
    ("write multiple registers 0..1 (read-only area)", mbap(b"\x10\x00\x00\x00\x02\x04\x00\x01\x00\x02"), ("exception", 0x02)),
    ("read holding registers (none exist)", mbap(b"\x03\x00\x00\x00\x01"), ("exception", 0x02)),
    ("read discrete inputs (none exist)", mbap(b"\x02\x00\x00\x00\x01"), ("exception", 0x02)),
    ("write multiple coils, byte count 2 for 1 coil", mbap(b"\x0f\x00\x00\x00\x01\x02\x01\x00"), ("exception", 0x03)),
    ("read input registers, PDU cut short inside a whole frame", mbap(b"\x04\x00\x00"), ("exception", 0x03)),
    ("unit id 7 (another server)", mbap(b"\x04\x00\x00\x00\x01", unit=7), "silent"),
    ("fc 0x84, an exception response sent as a request", mbap(b"\x84\x00\x00\x00\x01"), "silent"),
    ("MBAP protocol id 1 (not Modbus)", mbap(b"\x04\x00\x00\x00\x01", protocol=1), "silent"),
    ("MBAP length 0", mbap(b"", length=0), "closed"),
    ("MBAP length 300 (> 254)", mbap(b"\x04\x00\x00\x00\x01", length=300), "closed"),
    ("an HTTP request sent to the Modbus port", b"GET / HTTP/1.1\r\nHost: x\r\n\r\n", "closed"),
    ("truncated frame: MBAP says 6 bytes, 3 arrive, then silence", mbap(b"\x04\x00\x00\x00\x01")[:10], "closed"),
]


@pytest.mark.parametrize("frame, expected", [pytest.param(f, e, id=name) for name, f, e in MALFORMED])
def test_malformed_request_is_answered_as_the_protocol_says_and_the_server_keeps_serving(
        server: ModbusServerProcess, frame: bytes, expected: object) -> None:
    with socket.create_connection(("127.0.0.1", server.port), timeout=5) as sock:
        if expected == "silent":
            assert exchange(sock, frame, NO_REPLY_WAIT_S) is None
            # The same connection still serves: input register 1 is 241.
            assert exchange(sock, mbap(b"\x04\x00\x01\x00\x01")) == mbap(b"\x04\x02\x00\xf1")
        elif expected == "closed":
            sock.sendall(frame)
            assert closed_by_server(sock)
        else:
            _, code = expected  # type: ignore[misc]
            reply = exchange(sock, frame)
            assert reply == mbap(bytes([frame[7] | 0x80, code]), unit=frame[6]), reply
    assert_serves_the_image(server)


def test_clients_that_connect_and_never_read_neither_block_nor_keep_their_slot() -> None:
    proc = ModbusServerProcess("--idle-timeout-ticks", "100", *IMAGE_OPTIONS)
    try:
        # Four silent clients take every connection slot (kModbusMaxConnections = 4) ...
        silent = [socket.create_connection(("127.0.0.1", proc.port), timeout=5) for _ in range(4)]
        # ... a fifth is refused (accepted and closed at once) while they hold them ...
        with socket.create_connection(("127.0.0.1", proc.port), timeout=5) as fifth:
            assert closed_by_server(fifth)
        # ... and after the idle timeout (100 ticks) the server has closed them ...
        for sock in silent:
            assert closed_by_server(sock)
            sock.close()
        # ... so a real client is served again.
        assert_serves_the_image(proc)
    finally:
        _, lines = proc.stop()
    assert any("accepted 5, refused 1, idle timeouts 4" in line for line in lines), lines


def test_a_client_that_never_reads_its_replies_does_not_hold_up_another() -> None:
    proc = ModbusServerProcess(*IMAGE_OPTIONS)
    try:
        with socket.create_connection(("127.0.0.1", proc.port), timeout=5) as greedy:
            greedy.sendall(mbap(b"\x04\x00\x00\x00\x06") * 200)  # 200 requests, replies never read
            assert_serves_the_image(proc)
    finally:
        proc.stop()


def test_the_server_listens_on_the_loopback_interface_only(server: ModbusServerProcess) -> None:
    listening = []
    for line in open("/proc/net/tcp").read().splitlines()[1:]:
        local, state = line.split()[1], line.split()[3]
        address, port = local.split(":")
        if int(port, 16) == server.port and state == "0A":  # 0A = LISTEN
            listening.append(address)
    assert listening == ["0100007F"]  # 127.0.0.1, little-endian hex


def test_controlled_shutdown_closes_the_socket_and_disconnects_clients() -> None:
    proc = ModbusServerProcess(*IMAGE_OPTIONS)
    sock = socket.create_connection(("127.0.0.1", proc.port), timeout=5)
    assert exchange(sock, mbap(b"\x04\x00\x02\x00\x01")) == mbap(b"\x04\x02\x00\x64")
    code, lines = proc.stop()
    assert code == 0
    assert "stopped: 1 client connection(s) closed, accepted 1, refused 0, idle timeouts 0" in lines
    assert closed_by_server(sock)  # the server disconnected the client
    sock.close()
    with pytest.raises(ConnectionRefusedError):
        socket.create_connection(("127.0.0.1", proc.port), timeout=5)


def test_a_bad_option_is_a_one_line_error() -> None:
    proc = subprocess.run([str(SERVE), "--fan-percent", "140"], capture_output=True, text=True, timeout=10)
    assert proc.returncode == 2
    assert proc.stderr.splitlines()[0] == "pro_modbus_serve: --fan-percent: expected an integer in 0..100, got '140'"


def _exception_code(reply: object) -> int | None:
    return getattr(reply, "exception_code", None) if reply.isError() else None  # type: ignore[attr-defined]


def test_issue31_item6_a_client_off_the_allow_list_reads_but_every_write_is_refused_and_counted() -> None:
    """Issue 31 item 6: writes that change safety state only from an allow-listed client.
    The loopback interface is 127.0.0.0/8: a client bound to 127.0.0.2 is another client
    than one on 127.0.0.1, the only address on the allow-list."""
    proc = ModbusServerProcess("--allow-writes-from", "127.0.0.1", *IMAGE_OPTIONS)
    try:
        stranger = pymodbus_client.ModbusTcpClient("127.0.0.1", port=proc.port, timeout=2, retries=0,
                                                   source_address=("127.0.0.2", 0))
        assert stranger.connect()
        assert stranger.read_input_registers(3, count=1, device_id=UNIT).registers == [1]
        assert _exception_code(stranger.write_coil(1, True, device_id=UNIT)) == 0x01
        assert _exception_code(stranger.write_coil(0, True, device_id=UNIT)) == 0x01
        stranger.close()
        operator = client_for(proc)  # 127.0.0.1: on the list
        assert not operator.write_coil(1, True, device_id=UNIT).isError()
        assert not operator.write_coil(0, True, device_id=UNIT).isError()
        line = proc.next_line(5.0)
        assert line is not None and line.startswith("clear request taken at tick"), line
        operator.close()
    finally:
        code, lines = proc.stop()
    assert code == 0
    assert "frames write_not_allowed 2" in lines, lines


def test_issue31_item6_a_clear_needs_the_write_enable_just_before_and_uses_it_once() -> None:
    """Issue 31 item 6: the write-enable handshake: coil 1 := 1 arms one write to coil 0 of
    the same connection for the arm window; without it (or after it was used, or once it
    expired) the write is answered with exception 01 and counted."""
    proc = ModbusServerProcess("--arm-window-ticks", "400", *IMAGE_OPTIONS)  # 400 ticks of 5 ms: 2 s
    try:
        client = client_for(proc)
        assert _exception_code(client.write_coil(0, True, device_id=UNIT)) == 0x01
        assert not client.write_coil(1, True, device_id=UNIT).isError()
        assert client.read_coils(0, count=2, device_id=UNIT).bits[:2] == [False, True]  # armed
        assert not client.write_coil(0, True, device_id=UNIT).isError()
        line = proc.next_line(5.0)
        assert line is not None and line.startswith("clear request taken at tick"), line
        assert _exception_code(client.write_coil(0, True, device_id=UNIT)) == 0x01  # used up
        assert not client.write_coil(1, True, device_id=UNIT).isError()
        deadline = time.monotonic() + 30.0  # only ends a hung test
        while client.read_coils(1, count=1, device_id=UNIT).bits[0] and time.monotonic() < deadline:
            time.sleep(0.02)  # wait for the window to close (the server's ticks, not ours)
        assert _exception_code(client.write_coil(0, True, device_id=UNIT)) == 0x01  # expired
        client.close()
    finally:
        code, lines = proc.stop()
    assert code == 0
    assert "frames write_not_armed 3" in lines, lines

