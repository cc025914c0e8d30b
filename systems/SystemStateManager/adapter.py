"""Conformance adapter of the SystemStateManager: models/SystemStateManager.tla against
the C++ `safestate._core.Manager` (docs/design/system-state-manager.md).

This is the ONE place that knows the flagship's variables, inputs and calls; the rest
of `safestate conform` is generic (python/safestate/conform/adapter.py documents the
interface, docs/adding-a-system.md walks through writing one).

* Cycle(in): the model's abstract input record becomes raw channels (design §2): each
  channel level as is; selector AUTO/T1/T2 closes exactly that contact, INVALID none;
  speed ZERO / MOVING / OVER_T1 / OVER_T2 becomes joint velocities at a fixed pose,
  chosen with an independent reference kinematics (`tcp_speed_per_rad_s`: the DH product
  in Python) and checked against the C++ classification once.
* Submit(c): `manager.submit(kind, axis, direction, speed_mm_s)`; the C++ must answer
  QUEUE_FULL exactly when the model's queue is full.
* Projection: the §7 status variables as they are, `jog` split into jog_axis /
  jog_direction / jog_speed_mm_s, the §7 output operators; `queue` is observed through
  `queue_length`; inputs and the invariant history variables are not C++ state.
* Rows: `RowsFiredBy(in)` against `manager.last_rows()`.
* Input-complete alphabet: from each state, every value of each input dimension with
  the others held at the state's last inputs (every channel pair, every selector
  contact pattern, every enabling pair, concrete velocities just below / at / just
  above the zero and T1 thresholds, NaN, and each free signal); and, with the queue
  empty, a JOG_START at each bound of its argument check and of the T1 clamp
  (`jog_probes`, outside the cfg's JogCommands) followed by one cycle.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from types import ModuleType
from typing import Any

from hypothesis import strategies as st
from hypothesis.stateful import precondition, rule

from safestate.conform.adapter import Adapter, Applied, Probe
from safestate.conform.events import Event
from safestate.conform.model_step import ModelStepper
from safestate.tla.values import FnValue, Value

CYCLE = "Cycle"
SUBMIT = "Submit"
POSE = [0.0, -1.2, 1.1, -1.4, -1.57, 0.0]
BOOLS = (False, True)
ENABLE_POSITIONS = ("RELEASED", "MIDDLE", "PANIC")
SELECTOR_CONTACTS = ("selector_auto", "selector_t1", "selector_t2")
# Held signal groups: (fields of the model's input record), used by the Hypothesis rules.
GROUPS: dict[str, tuple[str, ...]] = {
    "estop": ("estop_a", "estop_b"), "gate": ("gate_a", "gate_b"),
    "enable": ("enable_a", "enable_b"), "selector": ("selector",),
}

# One disagreeing (or, for the selector, invalid) reading per held group: (model record
# fields, ScanInputs fields); the combined-disagreement probes hold two of them at once.
DISAGREEING: dict[str, tuple[dict[str, Any], dict[str, Any]]] = {
    "estop": ({"estop_a": True, "estop_b": False}, {"estop_closed_a": True, "estop_closed_b": False}),
    "gate": ({"gate_a": True, "gate_b": False}, {"safeguard_closed_a": True, "safeguard_closed_b": False}),
    "enable": ({"enable_a": "MIDDLE", "enable_b": "RELEASED"}, {"enabling_a": "MIDDLE", "enabling_b": "RELEASED"}),
    "selector": ({"selector": "INVALID"}, {"selector_auto": False, "selector_t1": False, "selector_t2": False}),
}


def selector_of(auto: bool, t1: bool, t2: bool) -> str:
    """Design §2: the mode whose contact alone is closed, else INVALID."""
    closed = [m for m, c in (("AUTO", auto), ("T1", t1), ("T2", t2)) if c]
    return closed[0] if len(closed) == 1 else "INVALID"


class SystemStateManagerAdapter(Adapter):
    observed_variables = ("state", "selector", "session_mode", "stop_category", "fault_code",
                          "last_reject_reason", "command_result", "estop_mismatch",
                          "safeguard_mismatch", "enabling_mismatch", "selector_invalid",
                          "state_cycles", "t2_confirmed", "resume_to", "axes",
                          # issue 17: the Reset interlock (K36 stale commands, K37 channel test).
                          "stale_commands", "estop_tested_a", "estop_tested_b",
                          # issue 29 item 6: K39's memory of a PANIC since the last RELEASED.
                          "enable_release_required",
                          # issue 29 item 10: C30's feedback monitors (FeedbackMonitor's counts).
                          "contactor_fb_cycles", "brake_fb_cycles")
    split_records = {"jog": (("jog_axis", "axis"), ("jog_direction", "direction"),
                             ("jog_speed_mm_s", "speed_mm_s"))}
    observed_operators = ("contactor_closed", "drive_enable", "brake_release", "ramp_down_request",
                          "reset_lamp", "commanded_speed_mm_s", "queue_length")
    hidden_variables = ("queue",  # observed through queue_length
                        "inputs", "event",
                        # the requirement observers (models/SystemStateManager.tla): history
                        # of inputs, commands and outputs, not C++ state.
                        "obs_estop", "obs_open_a", "obs_open_b", "obs_disagree", "obs_locked", "obs_ramp",
                        "last_accepted", "jog_in_auto", "obs_guard_fault", "obs_servo_on_powered", "obs_t2",
                        "obs_drive_fault", "obs_fieldbus_lost", "obs_unexpected_motion", "t1_overspeed",
                        "obs_booted", "obs_self_test_failed", "obs_arming", "obs_popped",
                        "obs_submit_lost", "obs_link_lost", "obs_was_enabled", "obs_ready_lost",
                        "obs_panic", "obs_t2_overspeed", "obs_fb_contactor", "obs_fb_brake",
                        "obs_was_released", "obs_jog_axis", "obs_ramp_cut",
                        # FeedbackMonitor's last command: read only while a disagreement
                        # counts, and then the command of the previous cycle (not in status).
                        "contactor_fb_cmd", "brake_fb_cmd")
    config_constants = {
        "DiscrepancyCycles": "discrepancy_cycles",
        "ArmingTimeoutCycles": "arming_timeout_cycles",
        "MaxStopCycles": "max_stop_cycles",
        "T2ConfirmTimeoutCycles": "t2_confirm_timeout_cycles",
        "T1SpeedLimit": "t1_speed_limit_mm_s",
        "T2SpeedLimit": "t2_speed_limit_mm_s",
        "QueueCapacity": "command_queue_limit",
        "FeedbackCycles": "feedback_allowed_cycles",
    }
    rows_operator = "RowsFiredBy"
    # Design page §6: "K17 after C13; K22 after C13; K23 and K28 after C11/C14".
    unreachable_rows = ("K17", "K22", "K23", "K28")

    def __init__(self, core: ModuleType, stepper: ModelStepper) -> None:
        super().__init__(core, stepper)
        self.cfg = self.config()
        self.queue_capacity = int(self.constants["QueueCapacity"])
        self.speeds = speed_vectors(core, self.cfg)
        self.jog_probes = jog_probes(int(self.constants["T1SpeedLimit"]), int(self.constants["T2SpeedLimit"]))
        self._raw_cache: dict[Value, dict[str, Any]] = {}
        self.discrepancy_cycles = int(self.constants["DiscrepancyCycles"])
        self._combined_seen: set[tuple[Value, Value]] = set()
        self._hazard_seen: set[tuple[Value, Value]] = set()

    def config(self) -> Any:
        """The model's constants, and the tool stated as a tool-less flange (design §9: a
        Config states its tool); the model abstracts the tool into `speed`."""
        cfg = super().config()
        cfg.tool_offset_m = (0.0, 0.0, 0.0)
        return cfg

    # ------------------------------------------------------------ C++ calls
    def new_sut(self) -> Any:
        return self.core.Manager(self.cfg)

    def raw(self, rec: dict[str, Value], key: Value | None = None) -> dict[str, Any]:
        """The ScanInputs dict for the model's abstract input record `rec`."""
        if key is not None and key in self._raw_cache:
            return self._raw_cache[key]
        sel = rec["selector"]
        d = {
            "estop_closed_a": rec["estop_a"], "estop_closed_b": rec["estop_b"],
            "safeguard_closed_a": rec["gate_a"], "safeguard_closed_b": rec["gate_b"],
            "enabling_a": rec["enable_a"], "enabling_b": rec["enable_b"],
            "selector_auto": sel == "AUTO", "selector_t1": sel == "T1", "selector_t2": sel == "T2",
            "self_test_ok": rec["self_test_ok"], "servo_ready": rec["servo_ready"],
            "drive_fault": rec["drive_fault"],
            # issue 17 (C24): the fieldbus/cycle watchdog input of ScanInputs.
            "fieldbus_ok": rec["fieldbus_ok"],
            # issue 16 (C26): the operator link's heartbeat monitor.
            "operator_link_ok": rec["operator_link_ok"],
            # issue 29 item 10 (C30): the contactor's auxiliary contact, the brakes' feedback.
            "contactor_feedback_closed": rec["contactor_fb"],
            "brake_feedback_released": rec["brake_fb"],
            "q": POSE, "qd": self.speeds[rec["speed"]][0],  # type: ignore[index]
        }
        if key is not None:
            self._raw_cache[key] = d
        return d

    def apply(self, sut: Any, event: Event, before: tuple) -> Applied:
        if event.action == CYCLE:
            sut.cycle(self.raw(event.record(), event.param()))
            return Applied(self._fired(sut))
        if event.action == SUBMIT:
            rec = event.record()
            full = len(before[self.index["queue"]]) >= self.queue_capacity  # type: ignore[arg-type]
            got = sut.submit(rec["kind"], rec["axis"], rec["direction"], rec["speed_mm_s"])
            want = "QUEUE_FULL" if full else "QUEUED"
            note = "" if got == want else f"submit returned {got}, the model's queue {'was' if full else 'was not'} full"
            return Applied(None, note)
        raise ValueError(f"unknown model action {event.action} (expected {CYCLE} or {SUBMIT})")

    @staticmethod
    def _fired(sut: Any) -> frozenset[str]:
        rows = sut.last_rows()
        return frozenset(r for r in (rows["cycle"], rows["command"]) if r is not None)

    # ------------------------------------------------- input-complete alphabet
    def input_alphabet(self, state: tuple) -> list[Probe]:
        cur: dict[str, Value] = dict(state[self.index["inputs"]].d)  # type: ignore[union-attr]
        base = self.raw(cur)
        probes: list[Probe] = []

        def add(label: str, changes: dict[str, Value], raw_changes: dict[str, Any]) -> None:
            rec = dict(cur, **changes)
            probes.append(Probe(Event.of(CYCLE, {"in": FnValue(rec)}), dict(base, **raw_changes), label))

        for a in BOOLS:
            for b in BOOLS:
                add(f"estop {a:d}{b:d}", {"estop_a": a, "estop_b": b}, {"estop_closed_a": a, "estop_closed_b": b})
                add(f"gate {a:d}{b:d}", {"gate_a": a, "gate_b": b},
                    {"safeguard_closed_a": a, "safeguard_closed_b": b})
        for ea in ENABLE_POSITIONS:
            for eb in ENABLE_POSITIONS:
                add(f"enabling {ea}/{eb}", {"enable_a": ea, "enable_b": eb}, {"enabling_a": ea, "enabling_b": eb})
        for pattern in range(8):
            contacts = [bool(pattern >> i & 1) for i in range(3)]
            add(f"selector contacts {pattern:03b}", {"selector": selector_of(*contacts)},
                dict(zip(SELECTOR_CONTACTS, contacts)))
        for label, level, qd in self.speeds["probes"]:
            add(f"speed: {label}", {"speed": level}, {"qd": qd})
        for name in ("servo_ready", "drive_fault", "self_test_ok", "fieldbus_ok", "operator_link_ok"):
            for v in BOOLS:
                add(f"{name} {v}", {name: v}, {name: v})
        for name, raw_name in (("contactor_fb", "contactor_feedback_closed"), ("brake_fb", "brake_feedback_released")):
            for v in BOOLS:
                add(f"{name} {v}", {name: v}, {raw_name: v})
        probes += self._combined_disagreement_probes(state, cur, base)
        probes += self._hazard_probes(state, cur, base)
        if not state[self.index["queue"]]:
            hold = Event.of(CYCLE, {"in": FnValue(cur)})
            for label, cmd in self.jog_probes:
                submit = Event.of(SUBMIT, {"c": FnValue(cmd)})
                probes.append(Probe(hold, [self.plan_call(submit), base], f"submit {label}, then hold the inputs",
                                    (submit,)))
        return probes

    def _combined_disagreement_probes(self, state: tuple, cur: dict[str, Value],
                                      base: dict[str, Any]) -> list[Probe]:
        """Two held groups disagreeing from the same cycle on, held D+1 cycles: both faults
        mature in one scan, so the C++ must report the model's (design §2) priority
        (`DiscrepancyFault`).  The one-group-per-cycle alphabet above never reaches this.
        Bounded: offered once per (control state, session mode), from the first probed
        state there whose mismatch counters are all 0, so it adds a few dozen probes."""
        key = (state[self.index["state"]], state[self.index["session_mode"]])
        counters = ("estop_mismatch", "safeguard_mismatch", "enabling_mismatch", "selector_invalid")
        if key in self._combined_seen or any(state[self.index[c]] for c in counters):
            return []
        self._combined_seen.add(key)
        out = []
        for g1, g2 in itertools.combinations(DISAGREEING, 2):
            rec = dict(cur, **DISAGREEING[g1][0], **DISAGREEING[g2][0])
            raw = dict(base, **DISAGREEING[g1][1], **DISAGREEING[g2][1])
            ev = Event.of(CYCLE, {"in": FnValue(rec)})
            out.append(Probe(ev, [raw] * (self.discrepancy_cycles + 1),
                             f"{g1} and {g2} disagreeing from one cycle on, held {self.discrepancy_cycles + 1} cycles",
                             (ev,) * self.discrepancy_cycles))
        return out

    def _hazard_probes(self, state: tuple, cur: dict[str, Value], base: dict[str, Any]) -> list[Probe]:
        """The reproductions of issue 29, named by the design page's unsafe control actions
        (§13): two inputs changing in one cycle and short command sequences that the
        one-dimension alphabet above does not contain.  Offered once per (control state,
        session mode), from the first probed state there with an empty queue."""
        key = (state[self.index["state"]], state[self.index["session_mode"]])
        if key in self._hazard_seen or state[self.index["queue"]]:
            return []
        self._hazard_seen.add(key)

        def cyc(model: dict[str, Value], raw: dict[str, Any]) -> tuple[Event, dict[str, Any]]:
            return Event.of(CYCLE, {"in": FnValue(dict(cur, **model))}), dict(base, **raw)

        def sub(kind: str) -> tuple[Event, Any]:
            ev = Event.of(SUBMIT, {"c": FnValue({"kind": kind, "axis": 0, "direction": 0, "speed_mm_s": 0})})
            return ev, self.plan_call(ev)

        def jog(axis: int) -> tuple[Event, Any]:
            ev = Event.of(SUBMIT, {"c": FnValue({"kind": "JOG_START", "axis": axis, "direction": 1,
                                                 "speed_mm_s": 100})})
            return ev, self.plan_call(ev)

        def seq(label: str, steps: list[tuple[Event, Any]]) -> Probe:
            events = tuple(e for e, _ in steps)
            return Probe(events[-1], [c for _, c in steps], label, events[:-1])

        estop = ({"estop_a": False, "estop_b": False}, {"estop_closed_a": False, "estop_closed_b": False})
        panic = ({"enable_a": "PANIC", "enable_b": "PANIC"}, {"enabling_a": "PANIC", "enabling_b": "PANIC"})
        middle = ({"enable_a": "MIDDLE", "enable_b": "MIDDLE"}, {"enabling_a": "MIDDLE", "enabling_b": "MIDDLE"})
        moving = ({"speed": "MOVING"}, {"qd": self.speeds["MOVING"][0]})
        unready = ({"servo_ready": False}, {"servo_ready": False})
        stop_cycles = int(self.constants["MaxStopCycles"]) + 2
        arming_cycles = int(self.constants["ArmingTimeoutCycles"]) + 2
        feedback_cycles = int(self.constants["FeedbackCycles"]) + 2
        # a stuck feedback: the opposite of what the outputs of this state command
        powered = state[self.index["state"]] in ("ARMING", "AUTO_IDLE", "AUTO_RUNNING", "MANUAL_IDLE",
                                                 "MANUAL_JOGGING", "STOPPING", "HOLD")
        stuck_contactor = not powered
        stuck_brake = not (powered and state[self.index["state"]] != "ARMING")
        return [
            seq("UCA-RSM-06 E-stop and a drive fault in one cycle",
                [cyc(dict(estop[0], drive_fault=True), dict(estop[1], drive_fault=True))]),
            seq("UCA-RSM-06 E-stop and servo_ready lost in one cycle",
                [cyc(dict(estop[0], **unready[0]), dict(estop[1], **unready[1]))]),
            seq("UCA-RSM-06 E-stop channel B and a T1 overspeed in one cycle",
                [cyc({"estop_b": False, "speed": "OVER_T1"},
                     {"estop_closed_b": False, "qd": self.speeds["OVER_T1"][0]})]),
            seq("UCA-RSM-12 E-stop channel B and a T2 overspeed in one cycle",
                [cyc({"estop_b": False, "speed": "OVER_T2"},
                     {"estop_closed_b": False, "qd": self.speeds["OVER_T2"][0]})]),
            seq("UCA-RSM-03 servo_ready lost, held 3 cycles", [cyc(*unready)] * 3),
            seq(f"UCA-RSM-13 contactor feedback stuck, {feedback_cycles} cycles",
                [cyc({"contactor_fb": stuck_contactor}, {"contactor_feedback_closed": stuck_contactor})]
                * feedback_cycles),
            seq(f"UCA-RSM-13 E-stop with the brake feedback stuck, {feedback_cycles} cycles",
                [cyc(dict(estop[0], brake_fb=stuck_brake), dict(estop[1], brake_feedback_released=stuck_brake))]
                * feedback_cycles),
            seq("UCA-RSM-15 contactor feedback disagreeing across a Servo-on, then the other way",
                [cyc({"contactor_fb": stuck_contactor}, {"contactor_feedback_closed": stuck_contactor}),
                 sub("SERVO_ON"),
                 cyc({"contactor_fb": not stuck_contactor}, {"contactor_feedback_closed": not stuck_contactor}),
                 cyc({"contactor_fb": stuck_contactor}, {"contactor_feedback_closed": stuck_contactor})]),
            seq("UCA-RSM-14 JOG_START on axis 4, then 2 cycles moving", [jog(4), cyc(*moving), cyc(*moving)]),
            seq("UCA-RSM-14 JOG_START on axis 7 (no such joint), then a cycle moving", [jog(7), cyc(*moving)]),
            seq("UCA-RSM-05 enabling PANIC, back to MIDDLE, then Servo-on",
                [cyc(*panic), cyc(*middle), sub("SERVO_ON"), cyc(*middle)]),
            seq(f"UCA-RSM-07 JOG_STOP with the arm still moving, {stop_cycles} cycles",
                [sub("JOG_STOP")] + [cyc(*moving)] * stop_cycles),
            seq(f"UCA-RSM-02 Servo-on without servo_ready, {arming_cycles} cycles",
                [sub("SERVO_ON")] + [cyc(*unready)] * arming_cycles),
        ]

    def probe_batch(self, prefix: list[Event], probes: list[Probe]) -> list[tuple[dict[str, Any], frozenset[str]]]:
        """Run each probe on a fresh C++ manager brought to the state by `prefix`."""
        out = self.core.probe(self.cfg, [self.plan_call(ev) for ev in prefix], [p.concrete for p in probes])
        return [(obs, frozenset(r for r in (rows["cycle"], rows["command"]) if r is not None))
                for obs, rows in out]

    # ------------------------------------------------- compact replay plan
    def fires_rows(self, event: Event) -> bool:
        return event.action == CYCLE

    def plan_call(self, event: Event) -> Any:
        """core.PlanReplayer's call: a cycle's ScanInputs dict or a submit tuple."""
        rec = event.record()
        if event.action == CYCLE:
            return self.raw(rec, event.param())
        return (rec["kind"], rec["axis"], rec["direction"], rec["speed_mm_s"])

    def plan_config(self) -> Any:
        return self.cfg

    def state_aux(self, state: tuple) -> int:
        """1 when the model's queue is full: a submit from this state must be QUEUE_FULL."""
        return 1 if len(state[self.index["queue"]]) >= self.queue_capacity else 0  # type: ignore[arg-type]

    def expected_line(self, state: tuple) -> str:
        """The binding's observe_key line for the model's projection of `state`."""
        if not hasattr(self, "_observe_keys"):
            self._observe_keys = list(self.new_sut().observe())
        d = self.project(state)
        return "".join(("1" if v else "0") + "|" if isinstance(v, bool) else
                       ",".join(v) + "|" if isinstance(v, list) else f"{v}|"
                       for v in (d[k] for k in self._observe_keys))

    def fast_replay(self, traces: list[Any], rows_at: list[int]) -> tuple[int, list[frozenset[str]]]:
        """The previous batched replay (`core.replay_compare`), kept for bench/bench_conform.py's
        comparison: whole traces in one binding call, the calls and expected lines interned
        per call in Python; (index of the first disagreeing trace or -1, the rows fired
        after each step of `rows_at`)."""
        if not hasattr(self, "_exp_ix"):
            self._exp_ix: dict[tuple, int] = {}
            self._exp: list[str] = []
        calls: list[Any] = []
        call_ix: dict[int, tuple[Event, int]] = {}    # id(event) -> (event kept alive, index)
        call_val: dict[Event, int] = {}
        steps: list[int] = []
        exp_ids: list[int] = []
        starts = [0]
        full: list[int] = []
        qix = self.index["queue"]
        cap = self.queue_capacity
        exp_ix, exp = self._exp_ix, self._exp
        by_id: dict[int, tuple[tuple, int]] = {}     # id(state) -> (state kept alive, index)
        for ct in traces:
            before = ct.initial
            for step in ct.steps:
                ev = step.event
                hit = call_ix.get(id(ev))
                if hit is None:
                    ci = call_val.get(ev)
                    if ci is None:
                        ci = call_val[ev] = len(calls)
                        calls.append(self.plan_call(ev))
                    hit = call_ix[id(ev)] = (ev, ci)
                steps.append(hit[1])
                state = step.state
                seen = by_id.get(id(state))
                if seen is None:
                    ei = exp_ix.get(state)
                    if ei is None:
                        ei = exp_ix[state] = len(exp)
                        exp.append(self.expected_line(state))
                    seen = by_id[id(state)] = (state, ei)
                exp_ids.append(seen[1])
                if ev.action == SUBMIT:
                    full.append(1 if len(before[qix]) >= cap else 0)  # type: ignore[arg-type]
                else:
                    full.append(0)
                before = state
            starts.append(len(steps))
        bad, _, rows = self.core.replay_compare(self.cfg, calls, steps, exp, exp_ids, starts, full, rows_at)
        return bad, [frozenset(r for r in pair if r is not None) for pair in rows]

    # ------------------------------------------------------ Hypothesis rules
    def hypothesis_rules(self) -> type:
        return flagship_rules(int(self.constants["DiscrepancyCycles"]), self.queue_capacity,
                              sorted({int(self.constants[k]) + d
                                      for k in ("ArmingTimeoutCycles", "MaxStopCycles", "T2ConfirmTimeoutCycles")
                                      for d in (-1, 0, 1, 2)} - {0}))


def jog_probes(t1_limit: int, t2_limit: int) -> list[tuple[str, dict[str, Value]]]:
    """JOG_START commands at each bound of K26's argument check (axis 1..6, direction
    -1/1, 0 < speed <= the T2 limit) and of the T1 clamp, beyond the cfg's JogCommands:
    the input-complete pass submits each (queue empty) and then runs one cycle."""
    def jog(axis: int, direction: int, speed: int) -> dict[str, Value]:
        return {"kind": "JOG_START", "axis": axis, "direction": direction, "speed_mm_s": speed}
    return [("JOG_START speed 0", jog(1, 1, 0)), ("JOG_START speed 1 mm/s", jog(1, 1, 1)),
            ("JOG_START axis 0", jog(0, 1, 100)), ("JOG_START axis 6", jog(6, -1, 100)),
            ("JOG_START direction 0", jog(1, 0, 100)),
            ("JOG_START exactly at the T1 limit", jog(1, 1, t1_limit)),
            ("JOG_START just above the T1 limit", jog(1, -1, t1_limit + 1)),
            ("JOG_START exactly at the T2 limit", jog(2, 1, t2_limit)),
            ("JOG_START just above the T2 limit", jog(2, -1, t2_limit + 1)),
            ("JOG_START at the largest int32", jog(1, 1, 2**31 - 1))]


def tcp_speed_per_rad_s(dh: list[tuple[float, ...]], q: list[float], joint: int) -> float:
    """Reference kinematics, independent of the C++: the TCP speed in mm/s for 1 rad/s of
    `joint` alone (standard DH rows (a_m, alpha_rad, d_m, theta_offset_rad)):
    |z_j x (p_tcp - p_j)| * 1000."""
    frames = [([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], [0.0, 0.0, 0.0])]
    for (a, alpha, d, off), qi in zip(dh, q):
        R, p = frames[-1]
        th = qi + off
        ct, st_, ca, sa = math.cos(th), math.sin(th), math.cos(alpha), math.sin(alpha)
        local = [[ct, -st_ * ca, st_ * sa], [st_, ct * ca, -ct * sa], [0.0, sa, ca]]
        t = [a * ct, a * st_, d]
        R2 = [[sum(R[i][k] * local[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        p2 = [p[i] + sum(R[i][k] * t[k] for k in range(3)) for i in range(3)]
        frames.append((R2, p2))
    R, p = frames[joint]
    z = [R[0][2], R[1][2], R[2][2]]
    r = [frames[-1][1][i] - p[i] for i in range(3)]
    v = [z[1] * r[2] - z[2] * r[1], z[2] * r[0] - z[0] * r[2], z[0] * r[1] - z[1] * r[0]]
    return 1000.0 * math.sqrt(sum(x * x for x in v))


def speed_vectors(core: ModuleType, config: Any) -> dict[str, Any]:
    """Joint velocities for each abstract speed level (level -> (qd, label)), and the
    threshold probes ('probes' -> [(label, level, qd)]), from the reference kinematics."""
    dh = [tuple(r) for r in config.dh]
    per_rad = tcp_speed_per_rad_s(dh, POSE, 0)  # mm/s per rad/s of joint 1
    limit = float(config.t1_speed_limit_mm_s)
    zero = float(config.zero_velocity_rad_s)
    cpp_per_rad = core.tcp_speed_mm_s(POSE, [1.0, 0, 0, 0, 0, 0], config)

    def exactly(bound: float) -> float:
        """Joint 1's rate whose TCP speed is `bound`. The C++ rounds differently in the
        last bits: nudge so that its own TCP speed is the bound exactly (the reference and
        the C++ agree to 1e-9 relative, checked here)."""
        w = bound / per_rad
        if abs(cpp_per_rad - per_rad) <= 1e-9 * per_rad:
            for _ in range(64):
                got = core.tcp_speed_mm_s(POSE, [w, 0, 0, 0, 0, 0], config)
                if got == bound:
                    break
                w = math.nextafter(w, math.inf if got < bound else -math.inf)
        return w
    at_limit = exactly(limit)
    at_t2 = exactly(float(config.t2_speed_limit_mm_s))

    def j1(v: float) -> list[float]:
        return [v, 0.0, 0.0, 0.0, 0.0, 0.0]
    moving = 0.5 * limit / per_rad
    if moving <= zero:
        raise ValueError("T1 limit too small for a MOVING velocity above the zero threshold")
    probes = [
        ("all joints 0", "ZERO", [0.0] * 6),
        ("joint 1 at the zero threshold", "ZERO", j1(zero)),
        ("joint 1 just above the zero threshold", "MOVING", j1(zero * 1.5)),
        ("joint 1 negative, above the zero threshold", "MOVING", j1(-zero * 1.5)),
        ("joint 6 alone above the zero threshold", "MOVING", [0.0] * 5 + [zero * 1.5]),
        ("TCP just below the T1 limit", "MOVING", j1(at_limit * 0.999)),
        ("TCP exactly at the T1 limit", "MOVING", j1(at_limit)),
        ("TCP just above the T1 limit", "OVER_T1", j1(at_limit * 1.001)),
        ("TCP above the T1 limit, joint 1 negative", "OVER_T1", j1(-at_limit * 1.001)),
        ("TCP exactly at the T2 limit", "OVER_T1", j1(at_t2)),
        ("TCP just above the T2 limit", "OVER_T2", j1(at_t2 * 1.001)),
        ("TCP above the T2 limit, joint 1 negative", "OVER_T2", j1(-at_t2 * 1.001)),
        ("NaN joint velocity", "OVER_T2", j1(math.nan)),
    ]
    if not at_limit < 0.5 * (at_limit + at_t2) < at_t2:
        raise ValueError("the T2 limit must lie above the T1 limit for an OVER_T1 velocity below it")
    return {"ZERO": ([0.0] * 6, "zero"), "MOVING": (j1(moving), "half the T1 limit"),
            "OVER_T1": (j1(0.5 * (at_limit + at_t2)), "between the T1 and the T2 limit"),
            "OVER_T2": (j1(2.0 * at_t2), "twice the T2 limit"), "probes": probes}


# ---------------------------------------------------------------------------
# Hypothesis rules: the shapes random walks rarely produce.  Mixed into the generic
# lockstep machine (python/safestate/conform/lockstep.py), whose helpers they use:
# self._pick(keep, i), self._inputs() (the model's last input record).
def flagship_rules(D: int, queue_capacity: int, timers: list[int]) -> type:  # noqa: C901
    class FlagshipRules:
        _pick: Callable[..., bool]
        _inputs: Callable[[], dict[str, Any]]

        def _held_only(self, group: str | None) -> Callable[[Event], bool]:
            """Cycles that change only `group` (None: change no held signal)."""
            cur = self._inputs()
            fields = GROUPS.get(group or "", ())
            held = [f for g in GROUPS.values() for f in g]

            def keep(e: Event) -> bool:
                if e.action != CYCLE:
                    return False
                rec = e.record()
                changed = [f for f in held if rec[f] != cur[f]]
                return bool(changed) and set(changed) <= set(fields) if group else not changed
            return keep

        def _set_group(self, group: str, want: Callable[[dict], bool], i: int = 0) -> bool:
            base = self._held_only(group)
            return self._pick(lambda e: base(e) and want(e.record()), i)

        def _submit(self, kind: str, i: int = 0) -> bool:
            return self._pick(lambda e: e.action == SUBMIT and e.record()["kind"] == kind, i)

        def _cycle_where(self, want: Callable[[dict], bool]) -> bool:
            base = self._held_only(None)
            return self._pick(lambda e: base(e) and want(e.record()), 0)

        @rule(i=st.integers(0, 255), n=st.integers(1, 3))
        def free_cycles(self, i: int, n: int) -> None:
            for _ in range(n):
                self._pick(self._held_only(None), i)

        @rule(group=st.sampled_from(sorted(GROUPS)), i=st.integers(0, 15))
        def change_group(self, group: str, i: int) -> None:
            self._set_group(group, lambda r: True, i)

        @rule(group=st.sampled_from(["estop", "gate", "enable"]), n=st.integers(2, 2 * D + 3),
              i=st.integers(0, 15))
        def bounce(self, group: str, n: int, i: int) -> None:
            """A channel pair flips back and forth every cycle."""
            a, b = GROUPS[group]
            home = (self._inputs()[a], self._inputs()[b])
            for k in range(n):
                if k % 2 == 0:
                    if not self._set_group(group, lambda r: True, i):
                        return
                elif not self._set_group(group, lambda r: (r[a], r[b]) == home):
                    return

        @rule(group=st.sampled_from(["estop", "gate", "enable"]), past=st.booleans())
        def stuck(self, group: str, past: bool) -> None:
            """One channel disagrees for exactly D cycles (tolerated) or D+1 (latches)."""
            a, b = GROUPS[group]
            home = (self._inputs()[a], self._inputs()[b])
            if not self._set_group(group, lambda r: r[a] != r[b]):
                return
            for _ in range(D - 1 + int(past)):
                if not self._pick(self._held_only(None), 0):
                    return
            self._set_group(group, lambda r: (r[a], r[b]) == home)

        @rule(picks=st.lists(st.integers(0, 63), min_size=1, max_size=queue_capacity + 2))
        def burst(self, picks: list[int]) -> None:
            """Commands submitted back to back: the queue fills, then rejects."""
            for i in picks:
                self._pick(lambda e: e.action == SUBMIT, i)

        @precondition(lambda self: self._inputs()["estop_a"] and self._inputs()["estop_b"])
        @rule(mode=st.sampled_from(["AUTO", "T1", "T2"]))
        def power_up(self, mode: str) -> None:
            """Drive toward an OPERATIONAL state (E-stop released): random walks rarely get there."""
            if self._inputs()["selector"] != mode:
                self._set_group("selector", lambda r: r["selector"] == mode)
            if mode != "AUTO":
                self._set_group("enable", lambda r: r["enable_a"] == r["enable_b"] == "MIDDLE")
            if mode == "T2":
                self._submit("T2_CONFIRM")
                self._cycle_where(lambda r: True)
            self._submit("SERVO_ON")
            self._cycle_where(lambda r: not r["servo_ready"] and not r["drive_fault"] and r["fieldbus_ok"])
            self._cycle_where(lambda r: r["servo_ready"] and not r["drive_fault"] and r["fieldbus_ok"])

        @rule(kind=st.sampled_from(["START", "JOG_START", "PAUSE", "RESUME", "JOG_STOP", "SERVO_OFF", "RESET"]),
              i=st.integers(0, 7))
        def command(self, kind: str, i: int) -> None:
            """One command and the cycle that pops it (the drives kept ready where offered)."""
            self._submit(kind, i)
            healthy = (lambda r: not r["drive_fault"] and r["fieldbus_ok"] and r["operator_link_ok"])
            if not self._cycle_where(lambda r: healthy(r) and r["servo_ready"]):
                self._cycle_where(healthy)

        @rule(n=st.sampled_from(timers), i=st.integers(0, 7))
        def hold(self, n: int, i: int) -> None:
            """Held cycles across the arming / stop timeouts (free signals by index)."""
            for _ in range(n):
                self._pick(self._held_only(None), i)

    return FlagshipRules


ADAPTER = SystemStateManagerAdapter
