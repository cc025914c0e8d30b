"""Conformance adapter of the protection active object: models/Protection.tla against the
C++ `safestate._pro.Protection` (ao_safety with sm_protection as an active object, its
output gate and ao_diagnostics, run in dispatch order once per tick; design §4, §11).

* Tick(t, v, ok, clr, hz, lc): one `tick(temp, volt, valid, clear, hazard_detected,
  lifecycle)`: the lifecycle event (EVT_DEGRADED / EVT_RECOVERY) is delivered to ao_safety
  before the tick's snapshot; the C++ reports the row of sm_protection that fired
  (compared with `RowsFiredBy`).
* Projection: the nine outputs of the tick (with `load_enable`, the equipment permissive,
  and `degraded`, ao_safety's degraded mode); the snapshot (inputs) and the history
  (`was_protection`, `hazard_ticks`) are not C++ state.  `fan_cmd` is read off the fan
  command the gate wrote: SAFE when it is the safe value, the control command (40 %)
  otherwise.
* Input-complete alphabet: every snapshot of the model, and the same abstract snapshot
  written with other concrete values: temperatures and voltages anywhere in the sensor's
  range on the same side of each limit (-40 degC and 150 degC, 0 V and 60 V, one past each
  limit), which the model's small alphabet stands for.
* Measured: the worst-case response in ticks (PRO-04) over every hazard episode the C++
  went through: ticks from the first hazardous snapshot of an episode until the C++ shows
  PROTECTION, the safe fan command and PROTECTION published (the budget is 10 ticks).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from safestate.conform.adapter import Adapter, Applied, Probe
from safestate.conform.events import Event
from safestate.tla.values import FnValue

TICK = "Tick"
# Concrete values standing for the model's extreme inputs (design §2: sensor range).
TEMP_MIN_C, TEMP_MAX_C, VOLT_MAX_DV = -40, 150, 600


@dataclass
class Chain:
    """The C++ chain and its hazard episode so far (for the response measurement)."""

    cpp: Any
    hazard_ticks: int = 0
    responded: bool = False


class ProtectionAdapter(Adapter):
    observed_variables = ("protection_state", "latch_active", "override_active", "fan_cmd", "load_enable",
                          "result", "published", "fault_event", "degraded")
    hidden_variables = ("temp", "volt", "valid", "clear", "hazard_in", "lifecycle", "was_protection",
                        "hazard_ticks")
    config_constants = {"TempLimit": "temp_limit", "VoltMin": "volt_min", "VoltMax": "volt_max"}
    rows_operator = "RowsFiredBy"

    def __init__(self, core: Any, stepper: Any) -> None:
        super().__init__(core, stepper)
        self.responses: list[int] = []   # ticks to respond, one per hazard episode
        self.unanswered = 0              # episodes that reached the budget without a response
        self.budget = int(stepper.constant("ResponseBudgetTicks"))

    # ------------------------------------------------------------ C++ calls
    def new_sut(self) -> Chain:
        return Chain(self.core.Protection(**{self.config_constants[k]: v for k, v in self.constants.items()}))

    def hazard(self, t: int, v: int, ok: bool, hz: bool) -> bool:
        """PRO-01's hazard, from the requirement's limits (not from the C++)."""
        c = self.constants
        return t > c["TempLimit"] or v < c["VoltMin"] or v > c["VoltMax"] or not ok or hz

    def tick(self, sut: Chain, t: int, v: int, ok: bool, clr: bool, hz: bool, lc: str) -> str:
        row: str = sut.cpp.tick(t, v, ok, clr, hz, lc)
        if not self.hazard(t, v, ok, hz):
            sut.hazard_ticks, sut.responded = 0, False
            return row
        sut.hazard_ticks += 1
        if not sut.responded:
            o = sut.cpp.observe()
            if (o["protection_state"] == "PROTECTION" and o["fan_cmd"] == "SAFE" and not o["load_enable"]
                    and o["published"] == "PROTECTION"):
                sut.responded = True
                self.responses.append(sut.hazard_ticks)
            elif sut.hazard_ticks == self.budget:
                self.unanswered += 1
        return row

    def apply(self, sut: Chain, event: Event, before: tuple) -> Applied:
        if event.action != TICK:
            raise ValueError(f"unknown model action {event.action} (expected {TICK})")
        p = dict(event.params)
        return Applied(frozenset({self.tick(sut, p["t"], p["v"], p["ok"], p["clr"], p["hz"], p["lc"])}))

    def observe(self, sut: Chain) -> dict[str, Any]:
        return sut.cpp.observe()  # type: ignore[no-any-return]

    def model_rows(self, state: tuple, event: Event) -> frozenset[str] | None:
        """`RowsFiredBy([t, v, ok, clr, hz, lc])`: Tick has six parameters, the operator takes their record."""
        return frozenset(self.stepper.applied("RowsFiredBy")(state, FnValue(dict(event.params))))  # type: ignore[arg-type]

    def measurements(self) -> dict[str, Any]:
        return {"hazard episodes": len(self.responses) + self.unanswered,
                "worst-case response (ticks)": max(self.responses, default=0),
                "episodes without a response within the budget": self.unanswered}

    # ------------------------------------------------------------ input-complete pass
    def input_alphabet(self, state: tuple) -> list[Probe]:
        """Every model snapshot, and each again with other concrete values of its class."""
        probes = []
        for event, _ in self.stepper.transitions(state):
            p = dict(event.params)
            probes.append(Probe(event, (p["t"], p["v"], p["ok"], p["clr"], p["hz"], p["lc"]), str(event)))
            for t, v, why in self._wider(p["t"], p["v"]):
                probes.append(Probe(event, (t, v, p["ok"], p["clr"], p["hz"], p["lc"]), f"{event}: {why}"))
        return probes

    def _wider(self, t: int, v: int) -> list[tuple[int, int, str]]:
        """Concrete values on the same side of every limit as (t, v), at the sensor's range ends."""
        c = self.constants
        out = []
        if t == 0:
            out.append((TEMP_MIN_C, v, f"temperature {TEMP_MIN_C}"))
        if t == c["TempLimit"] + 1:
            out.append((TEMP_MAX_C, v, f"temperature {TEMP_MAX_C}"))
        if v == c["VoltMin"] - 1:
            out.append((t, 0, "voltage 0"))
        if v == c["VoltMax"] + 1:
            out.append((t, VOLT_MAX_DV, f"voltage {VOLT_MAX_DV}"))
        return out

    def probe_batch(self, prefix: list[Event], probes: list[Probe]) -> list[tuple[dict[str, Any], frozenset[str]]]:
        results = []
        for p in probes:
            sut = self.new_sut()
            for event in prefix:
                self.apply(sut, event, ())
            row = sut.cpp.tick(*p.concrete)
            results.append((sut.cpp.observe(), frozenset({row})))
        return results


ADAPTER = ProtectionAdapter
