"""SAF-03: the Python binding of the Safety service (safestate._saf) rejects bad input
with a clear error, and its codec names each reject reason.  Its conformance to the
model runs in tests/python/test_conform_suite.py through systems/SafetyService/adapter.py."""

from __future__ import annotations

import pytest

_saf = pytest.importorskip("safestate._saf")


def test_saf_binding_rejects_bad_inbox_with_a_clear_error() -> None:
    svc = _saf.SafetyService(2, 3, 2)
    with pytest.raises(ValueError, match="inbox.estop: unknown value 'PRESSED'"):
        svc.cycle({"estop": "PRESSED", "health": "NONE", "control": "NONE", "hw_fault": False})
    with pytest.raises(ValueError, match="at least 1 cycle"):
        _saf.SafetyService(0, 3, 2)
    assert _saf.decode_error(b"\x01") == "TRUNCATED"


def test_saf_binding_exports_every_row_of_the_state_and_control_tables() -> None:
    rows = _saf.transition_table()
    assert [r["id"] for r in rows if r["table"] == "state"] == \
        ["F01", "E01", "P01", "P02", "P03", "O01", "O02", "O03", "M01", "M02"]
    assert [r["id"] for r in rows if r["table"] == "control"] == [f"K{i:02d}" for i in range(1, 11)]
