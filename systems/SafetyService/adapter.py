"""Conformance adapter of the Safety service: models/SafetyService.tla against the C++
`safestate._saf.SafetyService` (docs/design/safety-service.md §12).

* Cycle(in): the model's inbox is encoded into datagrams, each with the transport's
  intake verdict (sender, freshness: design §5), by the binding's `encode_inbox` (design
  §12) and sent through the codec path `cycle_raw(datagrams, in.hw_fault)`; every step
  also gets one garbage datagram (a different reject reason each step, at a different
  position among the valid ones), which must change nothing.
* Projection: the twelve service variables as they are; `inbox` (the input),
  `ever_faulted` and the h_* history of the message-level properties and `shadow` are
  not C++ state.
* Rows: `RowsFiredBy(in)` against the CycleResult's `state_row` and `control_row`.
* Input-complete alphabet: from each state, every model inbox, and the same abstract
  inboxes written differently on the wire: the other response codes and holders that
  mean the same control event, duplicated and superseded messages (the last of each
  kind wins), Report Subsystem State(EMERGENCY), outgoing message types, one datagram
  of every reject reason (design §5, §10), and every kind of attack datagram (each
  incoming type from another source, from the wrong peer, and replayed) added to every
  inbox, which must change nothing.  WARNING health is left out: the
  model's alphabet has no WARNING (it behaves as NORMAL in every row, but `observe()`
  reports it as WARNING; GoogleTest covers it).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from types import ModuleType
from typing import Any

from safestate.conform.adapter import Adapter, Applied, Probe
from safestate.conform.events import Event
from safestate.conform.model_step import ModelStepper

CYCLE = "Cycle"
# The Query Control period is not in the model (design §12: any value >= 1).
CHECK_INTERVAL_CYCLES = 3
OTHER_HOLDER = 0x0009_0909


def datagram(low_id: int, payload: bytes) -> bytes:
    """One datagram of design §10: u64 id (high word 1), u16 length, payload; little-endian."""
    return struct.pack("<QH", (1 << 32) | low_id, len(payload)) + payload


SET_ESTOP, REPORT_HEALTH, CONFIRM_CONTROL, REPORT_CONTROL = 0x13C, 0x13E, 0x12D, 0x12F
REPORT_SUBSYSTEM_STATE, QUERY_HEALTH, REQUEST_CONTROL, QUERY_CONTROL, SET_SUBSYSTEM_STATE = \
    0x13B, 0x13D, 0x12A, 0x12C, 0x139

# One datagram per reject reason of design §10 (checked against the C++ decoder at start-up).
GARBAGE: dict[str, bytes] = {
    "TRUNCATED": b"\x01",
    "OVERSIZED": datagram(SET_ESTOP, b"\x01") + bytes(60),
    "TRAILING_BYTES": datagram(SET_ESTOP, b"\x01") + b"\x00",
    "UNKNOWN_ID": datagram(0x777, b"\x01"),
    "BAD_LENGTH": datagram(SET_ESTOP, b"\x01\x01"),
    "FIELD_RANGE": datagram(SET_ESTOP, b"\x07"),
    "NOT_INCOMING": datagram(QUERY_CONTROL, b""),
}
# Accepted messages that change nothing the model sees: Report Subsystem State(EMERGENCY)
# (any other value is the model's subsys = "OPERATIONAL").
INERT: dict[str, bytes] = {"Report Subsystem State(EMERGENCY)": datagram(REPORT_SUBSYSTEM_STATE, b"\x02")}
OUTGOING = [datagram(QUERY_HEALTH, b""), datagram(QUERY_CONTROL, b""), datagram(REQUEST_CONTROL, bytes(6)),
            datagram(SET_SUBSYSTEM_STATE, b"\x02")]
# An earlier message of the same kind that the last one of the cycle overrides.
SUPERSEDED: dict[str, dict[str, tuple[bytes, ...]]] = {
    "estop": {"CLEAR": (datagram(SET_ESTOP, b"\x01"),), "SET": (datagram(SET_ESTOP, b"\x00"),)},
    "health": {"NORMAL": (datagram(REPORT_HEALTH, b"\x03"),), "ERROR": (datagram(REPORT_HEALTH, b"\x00"),),
               "FATAL": (datagram(REPORT_HEALTH, b"\x02"),)},
    "control": {"ACCEPTED": (datagram(CONFIRM_CONTROL, b"\x01"),), "REFUSED": (datagram(CONFIRM_CONTROL, b"\x00"),),
                "OTHER": (datagram(CONFIRM_CONTROL, b"\x00"),), "US": (datagram(CONFIRM_CONTROL, b"\x01"),)},
}
# The binding's PlanReplayer takes the peer as a number (safestate::saf::Peer).
PEER_CODE = {"CLIENT": 0, "SUBSYSTEM": 1, "OTHER": 2}


def attacks(core_component_id: int) -> list[tuple[str, tuple[bytes, str, bool]]]:
    """Every kind of attack datagram of issue 30 at the core's intake: each incoming type
    with each harmful content from another source, from the wrong peer, and replayed
    (stale) from the right one. Each must be rejected and change nothing."""
    us = struct.pack("<IB", core_component_id, 225)
    contents = [("Set Estop(CLEAR)", SET_ESTOP, b"\x00"), ("Set Estop(SET)", SET_ESTOP, b"\x01"),
                ("Report Health(NORMAL)", REPORT_HEALTH, b"\x00"), ("Report Health(FATAL)", REPORT_HEALTH, b"\x03"),
                ("Confirm Control(ACCEPTED)", CONFIRM_CONTROL, b"\x00"),
                ("Confirm Control(NOT_AVAILABLE)", CONFIRM_CONTROL, b"\x01"),
                ("Report Control(us)", REPORT_CONTROL, us),
                ("Report Control(other)", REPORT_CONTROL, struct.pack("<IB", OTHER_HOLDER, 255)),
                ("Report Subsystem State(OPERATIONAL)", REPORT_SUBSYSTEM_STATE, b"\x01")]
    out = []
    for label, low, payload in contents:
        d = datagram(low, payload)
        right = "CLIENT" if low == SET_ESTOP else "SUBSYSTEM"
        wrong = "SUBSYSTEM" if low == SET_ESTOP else "CLIENT"
        out.append((f"{label} from another source", (d, "OTHER", True)))
        out.append((f"{label} from the wrong peer", (d, wrong, True)))
        out.append((f"{label} replayed", (d, right, False)))
    return out


@dataclass
class Service:
    """The C++ service and how many steps it has taken (which garbage comes next)."""

    svc: Any
    steps: int = 0


class SafetyServiceAdapter(Adapter):
    observed_variables = ("state", "estop", "estop_age", "health", "health_age", "control",
                          "control_age", "out_request", "out_set_state", "alarm", "resend", "set_age")
    hidden_variables = ("inbox", "ever_faulted", "h_estop", "h_silence", "h_health", "h_health_age", "h_told",
                        "h_refused", "h_owed", "h_held_sent", "h_due", "h_due_age", "h_ask_age", "h_ask_refused",
                        "h_released_holding", "h_heeded", "h_held_age", "h_recheck_early", "h_set_age",
                        "h_resent_early", "shadow")
    config_constants = {
        "EstopTimeoutCycles": "estop_timeout_cycles",
        "ReportDataTimeoutCycles": "report_data_timeout_cycles",
        "MessageIntervalCycles": "message_interval_cycles",
    }
    rows_operator = "RowsFiredBy"

    def __init__(self, core: ModuleType, stepper: ModelStepper) -> None:
        super().__init__(core, stepper)
        self._encoded: dict[Any, list[tuple[bytes, str, bool]]] = {}
        self._alphabet: list[Probe] = []
        other = struct.pack("<IB", OTHER_HOLDER, 255)
        # The other messages that carry the same control event (design §5).
        self._control_alternatives: dict[str, tuple[tuple[str, bytes], ...]] = {
            "REFUSED": (("Confirm Control(INSUFFICIENT_AUTHORITY)", datagram(CONFIRM_CONTROL, b"\x02")),),
            "OTHER": (("Report Control(holder = nobody)", datagram(REPORT_CONTROL, struct.pack("<IB", 0, 0))),
                      ("Report Control(other holder, authority 1)", datagram(REPORT_CONTROL, other[:-1] + b"\x01"))),
        }
        self._attacks = attacks(core.COMPONENT_ID)
        self._check_codec()

    def _check_codec(self) -> None:
        """The hand-written datagrams are what the C++ codec means (else probes prove nothing)."""
        for reason, g in GARBAGE.items():
            svc = self.new_sut().svc
            svc.cycle_raw([g], False)
            rejected = {k: v for k, v in svc.diagnostics()["rejected"].items() if v}
            assert rejected == {reason: 1}, f"garbage for {reason}: the service rejected {rejected}"
        for label, d in INERT.items():
            assert self.core.decode_error(d) == "NONE", label
        set_estop = self.core.encode_inbox({"estop": "SET", "health": "NONE", "control": "NONE", "subsys": "NONE",
                                            "forged": "NONE", "hw_fault": False})
        assert set_estop == [(datagram(SET_ESTOP, b"\x01"), "CLIENT", True)], "datagram() disagrees with the C++ encoder"

    # ------------------------------------------------------------ C++ calls
    def new_sut(self) -> Service:
        c = self.constants
        return Service(self.core.SafetyService(c["EstopTimeoutCycles"], c["ReportDataTimeoutCycles"],
                                               c["MessageIntervalCycles"], CHECK_INTERVAL_CYCLES))

    def encoded(self, event: Event) -> list[tuple[bytes, str, bool]]:
        """The datagrams of the event's inbox with their intake verdicts (design §12), from
        the C++ encoder."""
        key = event.param()
        if key not in self._encoded:
            self._encoded[key] = list(self.core.encode_inbox(_plain_record(event)))
        return self._encoded[key]

    def apply(self, sut: Service, event: Event, before: tuple) -> Applied:
        if event.action != CYCLE:
            raise ValueError(f"unknown model action {event.action} (expected {CYCLE})")
        valid = self.encoded(event)
        garbage = list(GARBAGE.values())[sut.steps % len(GARBAGE)]
        at = sut.steps % (len(valid) + 1)
        sut.steps += 1
        result = sut.svc.cycle_raw(valid[:at] + [garbage] + valid[at:], bool(event.record()["hw_fault"]))
        return Applied(fired(result))

    def observe(self, sut: Service) -> dict[str, Any]:
        return sut.svc.observe()  # type: ignore[no-any-return]

    # ------------------------------------------------------------ compact replay plan
    def expected_line(self, state: tuple) -> str:
        """The binding's observe_line for the model's projection of `state`."""
        d = self.project(state)
        return "".join(f"{d[k]}|" for k in self.observed_variables)

    def plan_call(self, event: Event) -> tuple[list[tuple[bytes, int, bool]], bool]:
        """PlanReplayer's call: the inbox's datagrams (bytes, peer code, fresh) and the
        hardware fault line (the binding adds the garbage datagram of each step as `apply`
        does)."""
        return ([(d, PEER_CODE[p], f) for d, p, f in self.encoded(event)], bool(event.record()["hw_fault"]))

    def plan_config(self) -> Any:
        c = self.constants
        return ((c["EstopTimeoutCycles"], c["ReportDataTimeoutCycles"], c["MessageIntervalCycles"],
                 CHECK_INTERVAL_CYCLES), list(GARBAGE.values()))

    # ------------------------------------------------------------ input-complete pass
    def input_alphabet(self, state: tuple) -> list[Probe]:
        """The same alphabet in every state: the model's Inboxes are all enabled everywhere."""
        if not self._alphabet:
            for event, _ in self.stepper.transitions(state):
                self._alphabet.append(Probe(event, self.encoded(event), str(event)))
                self._alphabet.extend(self._rewritten(event))
        return self._alphabet

    def _rewritten(self, event: Event) -> list[Probe]:
        """The event's inbox written differently on the wire (design §5, §10)."""
        rec = event.record()
        valid = self.encoded(event)
        name = f"{event}"
        probes = []
        # Control events sent as the other messages that mean the same (design §5).
        control = [d for d in valid if _low_id(d[0]) in (CONFIRM_CONTROL, REPORT_CONTROL)]
        if control:
            at = valid.index(control[0])
            for label, d in self._control_alternatives.get(str(rec["control"]), ()):
                probes.append(Probe(event, valid[:at] + [(d, "SUBSYSTEM", True)] + valid[at + 1:], f"{name}: {label}"))
        # An earlier message of each kind that the last one overrides (from its own peer),
        # then every message twice: <= 11 datagrams.  Report Subsystem State is one of the
        # model's inputs (`subsys`), so it is not added here as if it changed nothing.
        first = [(d, "CLIENT" if k == "estop" else "SUBSYSTEM", True)
                 for k in ("estop", "health", "control") for d in SUPERSEDED[k].get(str(rec[k]), ())]
        probes.append(Probe(event, first + valid + valid,
                            f"{name}: superseded messages first, every message twice"))
        # One datagram of every reject reason and the outgoing types around the valid ones.
        probes.append(Probe(event, list(GARBAGE.values())[:4] + valid + list(GARBAGE.values())[4:] + OUTGOING,
                            f"{name}: every reject reason and outgoing message types"))
        # Every attack datagram after the valid ones (where it would win), in batches.
        room = self.core.MAX_INBOUND_PER_CYCLE - len(valid)
        for i in range(0, len(self._attacks), room):
            chunk = self._attacks[i:i + room]
            probes.append(Probe(event, valid + [a for _, a in chunk],
                                f"{name}: attack datagrams {', '.join(label for label, _ in chunk)}"))
        return probes

    def probe_batch(self, prefix: list[Event], probes: list[Probe]) -> list[tuple[dict[str, Any], frozenset[str]]]:
        sut = self.new_sut()
        for event in prefix:
            self.apply(sut, event, ())
        results = []
        for p in probes:
            svc = sut.svc.copy()
            result = svc.cycle_raw(p.concrete, bool(p.event.record()["hw_fault"]))
            results.append((svc.observe(), fired(result)))
        return results


def _low_id(d: bytes) -> int:
    return struct.unpack_from("<Q", d)[0] & 0xFFFF_FFFF


def fired(result: dict[str, Any]) -> frozenset[str]:
    """The rows of one CycleResult (the control row is empty when none fired)."""
    return frozenset(r for r in (result["state_row"], result["control_row"]) if r)


def _plain_record(event: Event) -> dict[str, Any]:
    return dict(event.record())


ADAPTER = SafetyServiceAdapter
