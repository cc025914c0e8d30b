"""`safestate demo press` (SCH-05): the flat model's counterexample inputs through both C++
presses side by side; the restart line is marked as the accident for the flat press only,
and the chain press's line shows it back at Ready with no stroke output."""

from __future__ import annotations

import pytest

from conftest import run_safestate

press = pytest.importorskip("safestate._press")
if not hasattr(press.HydraulicPress(), "active"):
    pytest.skip("safestate._press predates HydraulicPress.active(): run bash scripts/setup.sh",
                allow_module_level=True)


def test_SCH05_demo_press_marks_the_accident_on_the_flat_press_only() -> None:
    proc = run_safestate("demo", "press")
    assert proc.returncode == 0, proc.stderr
    scans = [ln for ln in proc.stdout.splitlines() if ln[:4].strip().isdigit()]
    assert [ln.split()[1] for ln in scans] == ["motor_on", "start", "motor_off", "motor_on", "step_done",
                                                "step_done"]
    marked = [ln for ln in scans if "ACCIDENT" in ln]
    assert len(marked) == 1 and marked[0].split()[0] == "4"
    flat, chain = marked[0].split("|")[1], marked[0].split("|")[2]
    assert "step Feed" in flat and "feed_valve" in flat
    assert "M1_Ready" in chain and "CoolIdle" in chain and "valve" not in chain.split("out")[1]
    assert "chain press too" not in proc.stdout


def test_demo_press_unknown_event_is_a_clear_error() -> None:
    proc = run_safestate("demo", "press", "--events", "motor_on,bogus")
    assert proc.returncode == 2
    assert "unknown press input event 'bogus'" in proc.stdout + proc.stderr
    assert "Traceback" not in proc.stderr
