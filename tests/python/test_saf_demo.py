"""SAF-01..04 end to end: `safestate demo saf` runs the C++ Safety service over UDP on the
loopback interface against the simulated Safety Client and subsystem and reaches the six
scenarios' outcomes (one line per change)."""

from __future__ import annotations

import pytest

from conftest import REPO, run_safestate

DEMO = REPO / "build" / "cpp" / "src" / "saf" / "saf_demo"


@pytest.mark.skipif(not DEMO.is_file(), reason="C++ tree not built (bash scripts/setup.sh)")
def test_saf_demo_reaches_the_six_scenarios_over_udp() -> None:
    proc = run_safestate("demo", "saf")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    out = proc.stdout
    for line in ("OPERATIONAL (from PAIRING, row P01)",      # 1. pairing -> operational (A)
                 "EMERGENCY   (from OPERATIONAL, row O02)",   # 2. E-stop / health -> emergency (C)
                 "OPERATIONAL (from EMERGENCY, row M01)",     # 3. clear -> operational (D)
                 "EMERGENCY   (from OPERATIONAL, row O01)",   # 4. Set Estop timeout (B)
                 "FAULT       (from OPERATIONAL, row E01)",   # 6. hardware fault (E)
                 "control HELD      | subsystem EMERGENCY   | holder safety service (225)",
                 "control REFUSED",
                 "rejected datagrams",
                 "all six scenarios reached their expected outcome"):
        assert line in out, line


def test_demo_unknown_system_is_a_clear_error() -> None:
    proc = run_safestate("demo", "nope")
    assert proc.returncode == 2
    assert "invalid choice: 'nope'" in proc.stderr
    assert "Traceback" not in proc.stderr
