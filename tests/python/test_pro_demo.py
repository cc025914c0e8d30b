"""PRO-01..05 end to end: `safestate demo protection` closes the C++ fan controller around
its thermal/electrical plant and shows over-temperature -> protection within the budget ->
a clear denied while hot -> accepted when cool; a supply dip -> Degraded -> recovery; the
controlled shutdown in its stop order (the demo checks each outcome itself)."""

from __future__ import annotations

import re

import pytest

from conftest import REPO, run_safestate

DEMO = REPO / "build" / "cpp" / "src" / "pro" / "pro_demo"


@pytest.mark.skipif(not DEMO.is_file(), reason="C++ tree not built (bash scripts/setup.sh)")
def test_pro_demo_shows_protection_latch_degraded_and_shutdown() -> None:
    proc = run_safestate("demo", "protection")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    out = proc.stdout
    assert re.search(r"PROTECTION RUN +R02  PROTECTION_ENTERED", out)
    assert "1 tick(s) after the first hazardous snapshot (budget 10)" in out
    assert re.search(r"PROTECTION RUN +R02  LATCH_BLOCKED", out)
    assert re.search(r"PROTECTION DEGRADED +R01  PROTECTION_ENTERED +\[mon,saf,dia\]", out)
    assert re.search(r"RUN +D01", out)
    steps = re.findall(r"waiting for step \d: (.*)", out)
    assert steps == ["outputs safe (control)", "stop comms", "stop diagnostics", "stop safety", "stop control",
                     "stop monitoring", "stop dispatcher", "stop timer"]
    assert re.search(r"STOPPED +S01", out)
    assert "check: " in out and ": NO" not in out
    assert "demo complete: 0 check(s) failed" in out
    # one line per tick, in order until the timer stops (the demo runs in real time beside
    # a client process: on a loaded machine a tick may be late and two share a line)
    ticks = [int(t) for t in re.findall(r"^t= *(\d+) ", out, re.M)]
    backwards = [(a, b) for a, b in zip(ticks, ticks[1:]) if b < a]
    assert ticks[0] == 1 and not backwards, backwards
