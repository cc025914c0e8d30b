"""The wire format of design §10, §14 and §15 in Python, for the simulators: written from the
design page, not from the C++, so that the three-process test also checks that two
implementations of the format (and of HMAC-SHA256: Python's hmac here) agree."""

from __future__ import annotations

import hashlib
import hmac
import struct
from dataclasses import dataclass

HEADER = struct.Struct("<QH")
HIGH = 0x0000_0001_0000_0000

SET_ESTOP = HIGH | 0x13C
REPORT_HEALTH_SUMMARY = HIGH | 0x13E
CONFIRM_CONTROL = HIGH | 0x12D
REPORT_CONTROL = HIGH | 0x12F
REPORT_SUBSYSTEM_STATE = HIGH | 0x13B
QUERY_HEALTH_SUMMARY = HIGH | 0x13D
REQUEST_CONTROL = HIGH | 0x12A
QUERY_CONTROL = HIGH | 0x12C
SET_SUBSYSTEM_STATE = HIGH | 0x139

HEALTH = {"NORMAL": 0, "WARNING": 1, "ERROR": 2, "FATAL": 3}
SUBSYSTEM_STATES = ["INITIALIZE", "OPERATIONAL", "EMERGENCY", "FAILURE"]
CONTROL_ACCEPTED, NOT_AVAILABLE, INSUFFICIENT_AUTHORITY = 0, 1, 2
ACTION_REQUEST, ACTION_RELEASE = 0, 1


def message(msg_id: int, payload: bytes = b"") -> bytes:
    return HEADER.pack(msg_id, len(payload)) + payload


def set_estop(emergency: bool, client_id: int, sequence: int, key: bytes | None) -> bytes:
    """The extension's Set Estop (§14): u8 emergency, u32 client id, u64 sequence, and the
    HMAC-SHA256 of every preceding byte when a key is given."""
    payload = struct.pack("<BIQ", 1 if emergency else 0, client_id, sequence)
    if key is None:
        return message(SET_ESTOP, payload)
    head = HEADER.pack(SET_ESTOP, len(payload) + 32) + payload
    return head + hmac.new(key, head, hashlib.sha256).digest()


# The authenticated service <-> subsystem link (design §15): the seed's message, its length
# field grown by the trailer, then u64 sequence and HMAC-SHA256(key, direction byte || every
# byte before the MAC). The direction byte keeps a message of one way from verifying the other.
TO_SUBSYSTEM, TO_SERVICE = 0x01, 0x02
LINK_TRAILER = 8 + 32
MAX_DATAGRAM = 64


def seal(datagram: bytes, sequence: int, direction: int, key: bytes | None) -> bytes:
    """The sealed form of a seed-form message; the message itself without a key."""
    if key is None:
        return datagram
    msg_id, length = HEADER.unpack_from(datagram)
    body = HEADER.pack(msg_id, length + LINK_TRAILER) + datagram[HEADER.size :] + struct.pack("<Q", sequence)
    return body + hmac.new(key, bytes([direction]) + body, hashlib.sha256).digest()


@dataclass
class LinkReceiver:
    """The receiving end's freshness state for one direction of the link."""

    window: int = 64
    highest: int | None = None


def open_sealed(data: bytes, direction: int, key: bytes, rx: LinkReceiver) -> tuple[str, bytes]:
    """("OK", the seed-form message) and `rx` advanced, or (reason, b"") with `rx` unchanged:
    UNAUTHENTICATED (no trailer), BAD_MAC, REPLAY (within the window), STALE."""
    if not HEADER.size + LINK_TRAILER <= len(data) <= MAX_DATAGRAM:
        return "UNAUTHENTICATED", b""
    msg_id, length = HEADER.unpack_from(data)
    if length != len(data) - HEADER.size:
        return "UNAUTHENTICATED", b""
    body, mac = data[:-32], data[-32:]
    if not hmac.compare_digest(mac, hmac.new(key, bytes([direction]) + body, hashlib.sha256).digest()):
        return "BAD_MAC", b""
    (sequence,) = struct.unpack_from("<Q", body, len(body) - 8)
    if rx.highest is not None and sequence <= rx.highest:
        return ("REPLAY" if rx.highest - sequence < rx.window else "STALE"), b""
    rx.highest = sequence
    return "OK", HEADER.pack(msg_id, length - LINK_TRAILER) + body[HEADER.size : -8]


def set_estop_seed(emergency: bool) -> bytes:
    return message(SET_ESTOP, bytes([1 if emergency else 0]))


def report_health(health: str) -> bytes:
    return message(REPORT_HEALTH_SUMMARY, bytes([HEALTH[health]]))


def confirm_control(code: int) -> bytes:
    return message(CONFIRM_CONTROL, bytes([code]))


def report_control(holder: int, authority: int) -> bytes:
    return message(REPORT_CONTROL, struct.pack("<IB", holder, authority))


def report_subsystem_state(state: str) -> bytes:
    return message(REPORT_SUBSYSTEM_STATE, bytes([SUBSYSTEM_STATES.index(state)]))


@dataclass(frozen=True)
class Outgoing:
    """A message the service sends to the subsystem, decoded (None: not one of them)."""

    kind: str  # "REQUEST_CONTROL", "QUERY_CONTROL", "SET_SUBSYSTEM_STATE", "QUERY_HEALTH_SUMMARY"
    action: int = 0
    authority: int = 0
    component_id: int = 0
    state: str = ""


def decode_outgoing(data: bytes) -> Outgoing | None:
    if len(data) < HEADER.size:
        return None
    msg_id, length = HEADER.unpack_from(data)
    payload = data[HEADER.size :]
    if len(payload) != length:
        return None
    if msg_id == REQUEST_CONTROL and length == 6:
        action, authority, component = struct.unpack("<BBI", payload)
        return Outgoing("REQUEST_CONTROL", action=action, authority=authority, component_id=component)
    if msg_id == QUERY_CONTROL and length == 0:
        return Outgoing("QUERY_CONTROL")
    if msg_id == QUERY_HEALTH_SUMMARY and length == 0:
        return Outgoing("QUERY_HEALTH_SUMMARY")
    if msg_id == SET_SUBSYSTEM_STATE and length == 1 and payload[0] < len(SUBSYSTEM_STATES):
        return Outgoing("SET_SUBSYSTEM_STATE", state=SUBSYSTEM_STATES[payload[0]])
    return None
