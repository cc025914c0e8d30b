"""Issue 31 item 2 under conformance (docs/design/hydraulic-press.md §8): the press adapter
compares the chain's active set, its call log of the scan (SCH-01..03: entry top-down, exit
leaf first, a scan without reaction calls nothing) and the mode parameters of the C++ press
with the model's, scan by scan, on the operator sequences of the issue: a mode selected with
the motor off is the mode of the restart, and a mode change mid-cycle exits the motor-on
subtree.  The whole reachable graph is replayed by tests/python/test_conform_suite.py."""

from __future__ import annotations

import pytest

from conftest import REPO
from safestate.checker.model import load_model
from safestate.conform.adapter import differing
from safestate.conform.cli import make_harness
from safestate.systems.registry import find

pytest.importorskip("safestate._press")
SYSTEM = find("HydraulicPress", REPO / "systems")


@pytest.fixture(scope="module")
def harness():  # type: ignore[no-untyped-def]
    model = load_model(str(SYSTEM.model), str(SYSTEM.conformance.config or SYSTEM.ci_config))
    return make_harness(SYSTEM, model)


def _lockstep(harness, events: list[str]) -> list[dict]:  # type: ignore[no-untyped-def]
    """Model and C++ through the same input events; the C++ observation after each scan,
    asserted equal to the model's projection (every observed key, the log included)."""
    stepper, adapter = harness.stepper, harness.adapter
    state = stepper.model.initial_states()[0]
    sut = adapter.new_sut()
    assert differing(adapter.project(state), adapter.observe(sut)) == []
    seen = []
    for e in events:
        event = next(ev for ev, _ in stepper.transitions(state) if str(ev.param()) == e)
        state = stepper.successor(state, event)
        adapter.apply(sut, event, ())
        got = adapter.observe(sut)
        assert differing(adapter.project(state), got) == [], (e, adapter.project(state), got)
        seen.append(got)
    return seen


def test_press_adapter_compares_active_set_call_log_and_parameters() -> None:
    assert {"active", "log"} <= set(SYSTEM.load_adapter_class().observed_variables)
    assert {"pressure", "speed", "mode"} <= set(SYSTEM.load_adapter_class().observed_operators)


def test_SCH05_mode_selected_with_motor_off_is_the_restarts_mode_in_model_and_cpp(harness) -> None:  # type: ignore[no-untyped-def]
    obs = _lockstep(harness, ["mode3", "motor_on", "motor_off", "mode2", "motor_on"])
    assert obs[-1]["mode"] == 2 and obs[-1]["step"] == "Ready"
    assert "M2_Ready" in obs[-1]["active"]


def test_SCH01_mode_change_mid_cycle_call_log_leaf_first_in_model_and_cpp(harness) -> None:  # type: ignore[no-untyped-def]
    obs = _lockstep(harness, ["motor_on", "start", "step_done", "mode2"])
    assert [(c["kind"], c["state"]) for c in obs[-1]["log"]] == [
        ("exit", "M1_CoolIdle"), ("exit", "M1_Aux"), ("exit", "M1_Locate"), ("exit", "M1_Stroke"),
        ("exit", "M1_On"), ("exit", "Mode1"), ("entry", "Mode2"), ("entry", "M2_Off")]
    assert obs[-1]["outputs"] == frozenset() and not obs[-1]["motor"]


def test_SCH05_each_mode_presses_with_its_own_pressure_in_model_and_cpp(harness) -> None:  # type: ignore[no-untyped-def]
    pressures = {}
    for mode, to_press in (("mode1", 5), ("mode2", 5), ("mode3", 4)):
        obs = _lockstep(harness, [mode, "motor_on", "start"] + ["step_done"] * (to_press - 1))
        assert obs[-1]["step"] == "Pressing"
        pressures[mode] = obs[-1]["pressure"]
    assert len(set(pressures.values())) == 3 and all(p > 0 for p in pressures.values())
