"""Replay of model steps through the C++ binding, compared after every step.

A `Lockstep` pairs one C++ Manager with one concrete model state.  `step(event,
expected)` performs the matching C++ call (Cycle -> manager.cycle(raw inputs),
Submit -> manager.submit(...)), then checks:

* Submit: the C++ answers QUEUE_FULL exactly when the model's queue was full;
* Cycle: the rows the C++ fired (`last_rows()`) are the rows the model fires
  (`RowsFiredBy(in)` evaluated in the state before the step), when asked;
* always: `observe()` equals the projection of the model's successor state.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any

from ..tla.values import fmt
from .diff import report
from .events import CYCLE, SUBMIT, Event
from .inputs import CONFIG_CONSTANTS, InputMapper, make_config, submit_args
from .model_step import ModelStepper
from .projection import Projection, differing


@dataclass
class Mismatch:
    step: int                 # 1-based index of the event in its trace
    event: Event
    model: dict[str, Any]
    cpp: dict[str, Any]
    message: str
    text: str = ""            # the rendered report

    def render(self) -> str:
        return self.text or report(self.step, str(self.event), self.model, self.cpp, self.message)


@dataclass
class Stats:
    steps: int = 0
    cycles: int = 0
    submits: int = 0
    rows: Counter = field(default_factory=Counter)        # C++ row id -> times fired
    row_checks: int = 0


class Harness:
    """What every lockstep shares: the model stepper, the C++ Config, the input
    mapping, the projection and the statistics."""

    def __init__(self, stepper: ModelStepper, core: ModuleType) -> None:
        self.stepper = stepper
        self.core = core
        self.constants = {k: stepper.constant(k) for k in CONFIG_CONSTANTS}
        self.config = make_config(core, self.constants)
        self.mapper = InputMapper(core, self.config)
        self.project = Projection(stepper)
        self.queue_capacity = int(self.constants["QueueCapacity"])
        self.has_rows = stepper.has("RowsFiredBy")
        self.stats = Stats()

    def lockstep(self, initial: tuple) -> "Lockstep":
        return Lockstep(self, initial)

    def model_rows(self, state: tuple, event: Event) -> set[str]:
        v = self.stepper.applied("RowsFiredBy")(state, event.param())
        return set(v)  # type: ignore[arg-type]


class Lockstep:
    def __init__(self, h: Harness, initial: tuple) -> None:
        self.h = h
        self.manager = h.core.Manager(h.config)
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
        note = ""
        if event.action == CYCLE:
            h.stats.cycles += 1
            rec = event.record()
            self.manager.cycle(h.mapper.raw(rec, event.param()))
            rows = self.manager.last_rows()
            fired = {r for r in (rows["cycle"], rows["command"]) if r is not None}
            for r in fired:
                h.stats.rows[r] += 1
            if check_rows and h.has_rows:
                h.stats.row_checks += 1
                want = h.model_rows(before, event)
                if want != fired:
                    note = f"rows: model fires {sorted(want)}, C++ fired {sorted(fired)}"
        elif event.action == SUBMIT:
            h.stats.submits += 1
            full = len(before[h.project.index_of("queue")]) >= h.queue_capacity
            got = self.manager.submit(*submit_args(event.record()))
            want = "QUEUE_FULL" if full else "QUEUED"
            if got != want:
                note = f"submit returned {got}, the model's queue {'was' if full else 'was not'} full"
        else:
            raise ValueError(f"unknown model action {event.action} (expected {CYCLE} or {SUBMIT})")
        self.state = after
        return self._compare(event, note)

    def _compare(self, event: Event, note: str) -> Mismatch | None:
        model = self.h.project(self.state)
        cpp = self.manager.observe()
        if note or differing(model, cpp):
            return Mismatch(self.index, event, model, cpp, note)
        return None


def describe(event: Event) -> str:
    return f"{event.action}({', '.join(f'{k}={fmt(v)}' for k, v in event.params)})"
