"""Replay of model steps through the C++ binding, compared after every step.

A `Lockstep` pairs one C++ object (the adapter's `new_sut()`) with one concrete model
state.  `step(event, expected)` performs the adapter's C++ call(s) for the event, then
checks:

* the adapter's note (e.g. the C++ answer to a submit disagreeing with the model);
* the rows the C++ fired are the rows the model fires (the adapter's rows operator,
  evaluated in the state before the step), when asked;
* always: the adapter's `observe()` equals its projection of the model's successor.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

from ..tla.values import fmt
from .adapter import Adapter, differing
from .diff import report
from .events import Event
from .model_step import ModelStepper


def describe(event: Event) -> str:
    """The event as a report shows it: with parameter names when there are several (an
    Event keeps them sorted by name, not in the action's order)."""
    if len(event.params) < 2:
        return str(event)
    return f"{event.action}({', '.join(f'{k}={fmt(v)}' for k, v in event.params)})"


@dataclass
class Mismatch:
    step: int                 # 1-based index of the event in its trace
    event: Event
    model: dict[str, Any]
    cpp: dict[str, Any]
    message: str
    text: str = ""            # the rendered report

    def render(self) -> str:
        return self.text or report(self.step, describe(self.event), self.model, self.cpp, self.message)


@dataclass
class Stats:
    steps: int = 0
    row_steps: int = 0       # steps that fire rows (cycles)
    rowless_steps: int = 0   # steps that fire none (submits)
    rows: Counter = field(default_factory=Counter)        # C++ row id -> times fired
    row_checks: int = 0


class Harness:
    """What every lockstep shares: the model stepper, the adapter and the statistics."""

    def __init__(self, stepper: ModelStepper, adapter: Adapter) -> None:
        self.stepper = stepper
        self.adapter = adapter
        self.core = adapter.core
        self.stats = Stats()

    def lockstep(self, initial: tuple) -> "Lockstep":
        return Lockstep(self, initial)


class Lockstep:
    def __init__(self, h: Harness, initial: tuple) -> None:
        self.h = h
        self.sut = h.adapter.new_sut()
        self.state = initial
        self.index = 0

    def check_initial(self) -> Mismatch | None:
        return self._compare(Event("Init", ()), "")

    def step(self, event: Event, expected: tuple | None = None, check_rows: bool = False) -> Mismatch | None:
        """Apply `event` to both sides; `expected` is the model successor if already
        known (else computed).  Returns the first disagreement, if any."""
        h = self.h
        before = self.state
        after = expected if expected is not None else h.stepper.successor(before, event)
        self.index += 1
        h.stats.steps += 1
        applied = h.adapter.apply(self.sut, event, before)
        note = applied.note
        if applied.fired is not None:
            h.stats.row_steps += 1
            for r in applied.fired:
                h.stats.rows[r] += 1
            if check_rows:
                want = h.adapter.model_rows(before, event)
                if want is not None:
                    h.stats.row_checks += 1
                    if want != applied.fired:
                        note = f"rows: model fires {sorted(want)}, C++ fired {sorted(applied.fired)}"
        else:
            h.stats.rowless_steps += 1
        self.state = after
        return self._compare(event, note)

    def _compare(self, event: Event, note: str) -> Mismatch | None:
        model = self.h.adapter.project(self.state)
        cpp = self.h.adapter.observe(self.sut)
        if note or differing(model, cpp):
            return Mismatch(self.index, event, model, cpp, note)
        return None
