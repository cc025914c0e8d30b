"""Conformance adapters of the hydraulic press (docs/design/hydraulic-press.md §7): the chain
press `safestate._press.HydraulicPress` against models/HydraulicPress.tla, and the flat
defective reference `safestate._press.PressFlat` against models/HydraulicPressFlat.tla.

* Scan(e): one `cycle(e)` with the operator input event e, spelt as in the model.
* Projection: the shared observables of both models (design §6): the operators `motor`,
  `mode`, `step` and the variable `outputs` (a set; the binding returns a sorted list).
  The chain press adds the mode parameters `pressure` and `speed` and the engine's own
  state: the active set `active` and the call log `log` of the scan (the entry/exit calls
  in order, SCH-01..04 compared call by call). The request and its result, and both
  models' history variables, are hidden.
* Input-complete alphabet: the twelve input events, enabled in every state of both models.
  The C++ press objects cannot be copied (the chain refers to its context), so each probe
  replays its prefix on a fresh press.
"""

from __future__ import annotations

from typing import Any, ClassVar

from safestate.conform.adapter import Adapter, Applied, Probe
from safestate.conform.events import Event

SCAN = "Scan"


class HydraulicPressAdapter(Adapter):
    observed_variables: ClassVar[tuple[str, ...]] = ("outputs", "active", "log")
    observed_operators: ClassVar[tuple[str, ...]] = ("motor", "mode", "step", "pressure", "speed")
    hidden_variables: ClassVar[tuple[str, ...]] = ("result", "request", "continuous", "restarted", "event",
                                                   "selector", "cycleMode", "clamped", "motorCmd", "cyclePos",
                                                   "coolDemand", "runSwitch")
    #: the class of safestate._press this adapter drives
    press_class: ClassVar[str] = "HydraulicPress"

    def new_sut(self) -> Any:
        return getattr(self.core, self.press_class)()

    def apply(self, sut: Any, event: Event, before: tuple) -> Applied:
        if event.action != SCAN:
            raise ValueError(f"unknown model action {event.action} (expected {SCAN})")
        sut.cycle(str(event.param()))
        return Applied(None)

    def observe(self, sut: Any) -> dict[str, Any]:
        o = dict(sut.observe())
        for key in ("outputs", "active"):  # sets in the model, sorted lists from the binding
            if key in o:
                o[key] = frozenset(o[key])
        return o

    def input_alphabet(self, state: tuple) -> list[Probe]:
        return [Probe(event, str(event.param()), str(event)) for event, _ in self.stepper.transitions(state)]

    def probe_batch(self, prefix: list[Event], probes: list[Probe]) -> list[tuple[dict[str, Any], frozenset[str]]]:
        results: list[tuple[dict[str, Any], frozenset[str]]] = []
        for p in probes:
            sut = self.new_sut()
            for event in prefix:
                self.apply(sut, event, ())
            sut.cycle(p.concrete)
            results.append((self.observe(sut), frozenset()))
        return results


class PressFlatAdapter(HydraulicPressAdapter):
    """DEFECTIVE REFERENCE: the flat press conforms to the flat model, accident included."""

    observed_variables = ("outputs",)
    observed_operators = ("motor", "mode", "step")
    hidden_variables = ("MoToOut", "cur", "FangShi", "continuous", "restarted", "event")
    press_class = "PressFlat"
