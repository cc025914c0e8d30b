"""Hypothesis lockstep testing: random event sequences applied to the model and the
C++ at once, compared after every step, shrunk to a minimal sequence on failure.

Every event is one the model allows in its current state (picked among the model's
own transitions, so input restrictions such as "one signal group changes per cycle"
are respected); the model successor is the unique transition with that event.
Rules produce the interesting shapes: any allowed event, one signal group changed,
a bouncing channel pair, a channel pair stuck in disagreement for exactly D and
D+1 cycles (the discrepancy limit and one past it), bursts of commands that fill
the queue, and runs of held cycles around the arming and stop timeouts.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, rule, run_state_machine_as_test

from ..checker.model import Model
from ..tla.values import FnValue
from .events import CYCLE, SUBMIT, Event
from .replay import Harness
from .traces import ConcreteTrace, Step

GROUPS: dict[str, tuple[str, ...]] = {
    "estop": ("estop_a", "estop_b"), "gate": ("gate_a", "gate_b"),
    "enable": ("enable_a", "enable_b"), "selector": ("selector",),
}
PROFILES = {  # SAFESTATE_CONFORM_PROFILE -> (examples per batch, rules per example)
    "default": (25, 40),
    "long": (200, 200),
}


class Counter:
    def __init__(self) -> None:
        self.steps = 0
        self.failure: str | None = None
        self.trace: ConcreteTrace | None = None


def make_machine(h: Harness, model: Model, count: Counter) -> type[RuleBasedStateMachine]:
    stepper = h.stepper
    inputs_ix = model.variables.index("inputs")
    D = int(h.constants["DiscrepancyCycles"])
    timers = sorted({int(h.constants[k]) + d for k in ("ArmingTimeoutCycles", "MaxStopCycles")
                     for d in (-1, 0, 1, 2)} - {0})
    initial = model.initial_states()[0]

    class Machine(RuleBasedStateMachine):
        def __init__(self) -> None:
            super().__init__()
            self.ls = h.lockstep(initial)
            self.steps: list[Step] = []

        # ---------------------------------------------------------------- helpers
        def _cur(self) -> dict[str, Any]:
            return self.ls.state[inputs_ix].d  # type: ignore[no-any-return]

        def _apply(self, event: Event, nxt: tuple) -> None:
            mm = self.ls.step(event, nxt, check_rows=True)
            count.steps += 1
            self.steps.append(Step(event, nxt, -1))
            if mm is not None:
                count.failure = mm.render()
                count.trace = ConcreteTrace(initial, list(self.steps))
                raise AssertionError(count.failure)

        def _pick(self, keep: Callable[[Event], bool], i: int) -> bool:
            """Apply the i-th (mod n) allowed event satisfying `keep`; False if none."""
            trs = [(e, s) for e, s in stepper.transitions(self.ls.state) if keep(e)]
            if not trs:
                return False
            event = trs[i % len(trs)][0]
            same = [s for e, s in trs if e == event]
            assert len(same) == 1, f"the model has {len(same)} transitions for {event}"
            self._apply(event, same[0])
            return True

        def _held_only(self, group: str | None) -> Callable[[Event], bool]:
            """Cycles that change only `group` (None: change no held signal)."""
            cur = self._cur()
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

        # ---------------------------------------------------------------- rules
        @rule(i=st.integers(0, 255))
        def any_event(self, i: int) -> None:
            self._pick(lambda e: True, i)

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
            home = (self._cur()[a], self._cur()[b])
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
            home = (self._cur()[a], self._cur()[b])
            if not self._set_group(group, lambda r: r[a] != r[b]):
                return
            for _ in range(D - 1 + int(past)):
                if not self._pick(self._held_only(None), 0):
                    return
            self._set_group(group, lambda r: (r[a], r[b]) == home)

        @rule(picks=st.lists(st.integers(0, 63), min_size=1, max_size=h.queue_capacity + 2))
        def burst(self, picks: list[int]) -> None:
            """Commands submitted back to back: the queue fills, then rejects."""
            for i in picks:
                self._pick(lambda e: e.action == SUBMIT, i)

        def _submit(self, kind: str, i: int = 0) -> bool:
            return self._pick(lambda e: e.action == SUBMIT and e.record()["kind"] == kind, i)

        def _cycle_where(self, want: Callable[[dict], bool]) -> bool:
            base = self._held_only(None)
            return self._pick(lambda e: base(e) and want(e.record()), 0)

        @rule(mode=st.sampled_from(["AUTO", "T1", "T2"]))
        def power_up(self, mode: str) -> None:
            """Drive toward an OPERATIONAL state: random walks rarely get there."""
            if self._cur()["selector"] != mode:
                self._set_group("selector", lambda r: r["selector"] == mode)
            if mode != "AUTO":
                self._set_group("enable", lambda r: r["enable_a"] == r["enable_b"] == "MIDDLE")
            if mode == "T2":
                self._submit("T2_CONFIRM")
                self._cycle_where(lambda r: True)
            self._submit("SERVO_ON")
            self._cycle_where(lambda r: not r["servo_ready"] and not r["drive_fault"])
            self._cycle_where(lambda r: r["servo_ready"] and not r["drive_fault"])

        @rule(kind=st.sampled_from(["START", "JOG_START", "PAUSE", "RESUME", "JOG_STOP", "SERVO_OFF", "RESET"]),
              i=st.integers(0, 7))
        def command(self, kind: str, i: int) -> None:
            """One command and the cycle that pops it."""
            self._submit(kind, i)
            self._cycle_where(lambda r: not r["drive_fault"])

        @rule(n=st.sampled_from(timers), i=st.integers(0, 7))
        def hold(self, n: int, i: int) -> None:
            """Held cycles across the arming / stop timeouts (free signals by index)."""
            for _ in range(n):
                self._pick(self._held_only(None), i)

    return Machine


def run_lockstep(h: Harness, model: Model, min_steps: int, profile: str | None = None,
                 progress: Callable[[str], None] | None = None,
                 seed: int | None = None) -> tuple[int, str | None]:
    """Run until at least `min_steps` steps; (steps, failure report or None)."""
    profile = profile or os.environ.get("SAFESTATE_CONFORM_PROFILE", "default")
    examples, rules = PROFILES[profile]
    count = Counter()
    machine = make_machine(h, model, count)
    batch = 0
    while count.steps < min_steps:
        s = settings(max_examples=examples, stateful_step_count=rules, deadline=None, database=None,
                     suppress_health_check=list(HealthCheck), derandomize=seed is not None)
        try:
            if seed is not None:
                machine.TestCase.settings = s
            run_state_machine_as_test(machine, settings=s)
        except AssertionError:
            return count.steps, f"Hypothesis (shrunk):\n{count.failure}"
        batch += 1
        if progress:
            progress(f"conform: hypothesis {count.steps} steps ({batch} batches)")
    return count.steps, None
