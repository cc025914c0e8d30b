"""Hypothesis lockstep testing: random event sequences applied to the model and the
C++ at once, compared after every step, shrunk to a minimal sequence on failure.

Every event is one the model allows in its current state (picked among the model's
own transitions, so the model's input restrictions are respected); the model
successor is the unique transition with that event.  The generic machine has one
rule, `any_event`, and an invariant that the C++ still observes what the model
projects; the system's adapter adds rules for the shapes random walks rarely reach
(`Adapter.hypothesis_rules()`, e.g. the flagship's bouncing channel pairs).

Profiles are Hypothesis settings profiles (`safestate-default`, `safestate-long`,
chosen by SAFESTATE_CONFORM_PROFILE); a seed makes a run reproducible.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

from hypothesis import HealthCheck, Phase, settings
from hypothesis import seed as hypothesis_seed
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule, run_state_machine_as_test

from ..checker.model import Model
from .adapter import differing
from .events import Event
from .replay import Harness
from .traces import ConcreteTrace, Step

PROFILE_ENV = "SAFESTATE_CONFORM_PROFILE"
for _name, _examples, _rules in (("default", 25, 40), ("long", 200, 200)):
    settings.register_profile(f"safestate-{_name}", max_examples=_examples, stateful_step_count=_rules,
                              deadline=None, database=None, suppress_health_check=list(HealthCheck))


class Counter:
    def __init__(self) -> None:
        self.steps = 0
        self.failure: str | None = None
        self.trace: ConcreteTrace | None = None


class LockstepMachine(RuleBasedStateMachine):
    """The generic lockstep machine: one rule (`any_event`) and one invariant (the C++
    observes what the model projects).  Unbound: `make_machine` subclasses it with the
    harness, the model's initial state and the step counter."""

    harness: Harness
    initial: tuple
    count: Counter

    def __init__(self) -> None:
        super().__init__()
        self.ls = self.harness.lockstep(self.initial)
        self.steps: list[Step] = []

    def _inputs(self) -> dict[str, Any]:
        """The model's last input record (for adapter rules that change one signal)."""
        inputs_ix = self.harness.adapter.index.get("inputs")
        assert inputs_ix is not None, "the model has no `inputs` variable"
        return self.ls.state[inputs_ix].d  # type: ignore[no-any-return]

    def _apply(self, event: Event, nxt: tuple) -> None:
        mm = self.ls.step(event, nxt, check_rows=True)
        self.count.steps += 1
        self.steps.append(Step(event, nxt, -1))
        if mm is not None:
            self._fail(mm.render())

    def _fail(self, text: str) -> None:
        self.count.failure = text
        self.count.trace = ConcreteTrace(self.initial, list(self.steps))
        raise AssertionError(text)

    def _pick(self, keep: Callable[[Event], bool], i: int) -> bool:
        """Apply the i-th (mod n) allowed event satisfying `keep`; False if none."""
        trs = [(e, s) for e, s in self.harness.stepper.transitions(self.ls.state) if keep(e)]
        if not trs:
            return False
        event = trs[i % len(trs)][0]
        same = [s for e, s in trs if e == event]
        assert len(same) == 1, f"the model has {len(same)} transitions for {event}"
        self._apply(event, same[0])
        return True

    @rule(i=st.integers(0, 255))
    def any_event(self, i: int) -> None:
        self._pick(lambda e: True, i)

    @invariant()
    def cpp_observes_the_model_state(self) -> None:
        adapter = self.harness.adapter
        bad = differing(adapter.project(self.ls.state), adapter.observe(self.ls.sut))
        if bad:
            self._fail(f"after step {self.ls.index}: observe() differs from the model in {', '.join(bad)}")


def bind_machine(h: Harness, initial: tuple, count: Counter) -> type[LockstepMachine]:
    """The generic machine bound to one harness, initial state and counter."""
    return type("Lockstep", (LockstepMachine,), {"harness": h, "initial": initial, "count": count})


def make_machine(h: Harness, model: Model, count: Counter) -> type[RuleBasedStateMachine]:
    """The generic lockstep machine, with the adapter's rules mixed in."""
    base = bind_machine(h, model.initial_states()[0], count)
    rules = h.adapter.hypothesis_rules()
    if rules is None:
        return base
    return type("Lockstep" + type(h.adapter).__name__, (rules, base), {})


def run_lockstep(h: Harness, model: Model, min_steps: int, profile: str | None = None,
                 progress: Callable[[str], None] | None = None,
                 seed: int | None = None, shrink: bool = True) -> tuple[int, str | None]:
    """Run until at least `min_steps` steps; (steps, failure report or None).

    shrink=False reports the first failing run as found: for a caller that only needs to
    know a wrong build is caught (shrinking can cost minutes), not a minimal reproducer."""
    profile = profile or os.environ.get(PROFILE_ENV, "default")
    s = settings.get_profile(f"safestate-{profile}")
    if not shrink:
        s = settings(s, phases=[p for p in Phase if p is not Phase.shrink])
    count = Counter()
    machine = make_machine(h, model, count)
    batch = 0
    while count.steps < min_steps:
        if seed is not None:
            hypothesis_seed(seed + batch)(machine)
        try:
            run_state_machine_as_test(machine, settings=s)
        except AssertionError:
            found = "shrunk" if shrink else "first failing run, not shrunk"
            return count.steps, f"Hypothesis ({found}):\n{count.failure}"
        batch += 1
        if progress:
            progress(f"conform: hypothesis {count.steps} steps ({batch} batches)")
    return count.steps, None
