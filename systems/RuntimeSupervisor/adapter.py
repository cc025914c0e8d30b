"""Conformance adapter of the runtime supervisor: models/RuntimeSupervisor.tla against the
C++ `safestate._pro.Supervisor` (RuntimeSupervisor, rows X01..T01 as a constexpr table,
and the dispatch cycle; design §6-§8, §11).

* Tick(ev): one `tick(kind, unit)`.  The C++ object is the real supervisor and dispatcher
  with a test double of the seven units: the model's environment event of the tick sets
  the units' reports (READY, FAIL), the fatal-fault and watchdog lines, the shutdown
  request, or - for STOPPED - the report of the unit the supervisor asked to stop (step 1:
  control reports the outputs safe).  The C++ reports the row that fired (`RowsFiredBy`).
* Projection: `sup_state`, `status`, `init_ticks`, `stop_step`, `outputs_safe`,
  `dispatched`, `safety_input` (what ao_safety evaluated: `safety_input_of` the real
  dispatch record) and `outputs` (the output stage after the tick); the fault lines
  `fatal_fault`, `watchdog_ok` are inputs, `init_age`, `shutdown_requested` and
  `stop_reports` are the model's observers.
* The dispatcher gate is the runtime's `dispatch_gate`: no dispatch cycle while the
  dispatcher unit is not READY.
* Replay of the 178,041 transitions runs as a compact plan in the binding (`PlanReplayer`).
* Input-complete alphabet: every model event, plus the reports the model leaves out
  because they change nothing, each probed as the model's NONE: a unit reporting the
  status it already has, a fault line set to the value it has, a shutdown request while
  shutting down or stopped, a fault line changing while shutting down or stopped, a stop
  report once STOPPED.
"""

from __future__ import annotations

from typing import Any

from hypothesis import strategies as st
from hypothesis.stateful import rule

from safestate.conform.adapter import Adapter, Applied, Probe
from safestate.conform.events import Event
from safestate.tla.values import FnValue

TICK = "Tick"
UNITS = ("timer", "dispatcher", "monitoring", "control", "safety", "diagnostics", "comms")
LIVE = ("INIT", "RUN", "DEGRADED")


def call(event: Event) -> tuple[str, str]:
    rec = event.record()
    return str(rec["kind"]), str(rec["unit"])


class RuntimeSupervisorAdapter(Adapter):
    observed_variables = ("sup_state", "status", "init_ticks", "stop_step", "outputs_safe", "dispatched",
                          "safety_input", "outputs")
    hidden_variables = ("fatal_fault", "watchdog_ok", "init_age", "shutdown_requested", "stop_reports")
    config_constants = {"InitTimeoutTicks": "init_timeout_ticks"}
    rows_operator = "RowsFiredBy"

    def __init__(self, core: Any, stepper: Any) -> None:
        super().__init__(core, stepper)
        self._none = Event.of(TICK, {"ev": FnValue({"kind": "NONE", "unit": "none"})})

    # ------------------------------------------------------------ C++ calls
    def new_sut(self) -> Any:
        return self.core.Supervisor(self.constants["InitTimeoutTicks"])

    def apply(self, sut: Any, event: Event, before: tuple) -> Applied:
        if event.action != TICK:
            raise ValueError(f"unknown model action {event.action} (expected {TICK})")
        return Applied(frozenset({sut.tick(*call(event))}))

    def table_rows(self) -> list[str]:
        return [r["id"] for r in self.core.supervisor_table()]

    # ------------------------------------------------------------ compact replay plan
    def expected_line(self, state: tuple) -> str:
        """The binding's key() line for the model's projection of `state`."""
        d = self.project(state)
        status = "".join(f"{d['status'][u]}," for u in UNITS)
        return (f"{d['sup_state']}|{status}|{d['init_ticks']}|{d['stop_step']}|{int(d['outputs_safe'])}|"
                + "".join(f"{a}," for a in d["dispatched"]) + f"|{d['safety_input']}|{d['outputs']}")

    def plan_call(self, event: Event) -> tuple[str, str]:
        return call(event)

    def plan_config(self) -> Any:
        return self.constants["InitTimeoutTicks"]

    # ------------------------------------------------------------ input-complete pass
    def input_alphabet(self, state: tuple) -> list[Probe]:
        probes = [Probe(event, call(event), str(event)) for event, _ in self.stepper.transitions(state)]
        return probes + [Probe(self._none, c, f"{c[0]} {c[1]}: changes nothing") for c in self._inert(state)]

    def _inert(self, state: tuple) -> list[tuple[str, str]]:
        """Concrete reports the model leaves out because they change nothing (as NONE)."""
        sup = state[self.index["sup_state"]]
        status = state[self.index["status"]].d  # type: ignore[union-attr]
        fatal, wd = state[self.index["fatal_fault"]], state[self.index["watchdog_ok"]]
        if sup in LIVE:
            out = [("READY", u) for u in UNITS if status[u] == "READY"]
            out += [("FAIL", u) for u in UNITS if status[u] == "FAILED"]
            out.append(("FATAL_SET", "none") if fatal else ("FATAL_CLEAR", "none"))
            out.append(("WD_OK", "none") if wd else ("WD_BAD", "none"))
            return out
        out = [("SHUTDOWN", "none"), ("FATAL_SET", "none"), ("FATAL_CLEAR", "none"), ("WD_BAD", "none"),
               ("WD_OK", "none")]
        return out + ([("STOPPED", "none")] if sup == "STOPPED" else [])

    def probe_batch(self, prefix: list[Event], probes: list[Probe]) -> list[tuple[dict[str, Any], frozenset[str]]]:
        sut = self.new_sut()
        for event in prefix:
            sut.tick(*call(event))
        results = []
        for p in probes:
            copy = sut.copy()
            row = copy.tick(*p.concrete)
            results.append((copy.observe(), frozenset({row})))
        return results

    # ------------------------------------------------------ Hypothesis rules
    def hypothesis_rules(self) -> type:
        return supervisor_rules()


def supervisor_rules() -> type:
    """Rules for the shapes a uniform random walk rarely reaches: every unit ready (RUN),
    every unit ready again after a fault (recovery), and a whole controlled shutdown (a
    shutdown request, then stop reports in a row)."""

    def kind_is(*kinds: str) -> Any:
        return lambda e: e.record()["kind"] in kinds

    class SupervisorRules:
        @rule(i=st.integers(0, 6))
        def bring_up(self, i: int) -> None:
            for _ in range(len(UNITS)):
                self._pick(kind_is("READY"), i)  # type: ignore[attr-defined]

        @rule(k=st.integers(0, 8), i=st.integers(0, 6))
        def fault_then_bring_up(self, k: int, i: int) -> None:
            # Degraded with every unit ready again: the shape of recovery (D01) and of a
            # recovery that must not happen while a fault line stays set (D02).
            self._pick(kind_is("FAIL", "FATAL_SET", "WD_BAD"), k)  # type: ignore[attr-defined]
            for _ in range(len(UNITS)):
                self._pick(kind_is("READY"), i)  # type: ignore[attr-defined]

        @rule(n=st.integers(1, 10))
        def controlled_shutdown(self, n: int) -> None:
            self._pick(kind_is("SHUTDOWN"), 0)  # type: ignore[attr-defined]
            for _ in range(n):
                self._pick(kind_is("STOPPED"), 0)  # type: ignore[attr-defined]

    return SupervisorRules


ADAPTER = RuntimeSupervisorAdapter
