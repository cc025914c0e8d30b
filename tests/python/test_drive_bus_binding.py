"""Issue 29 item 10 through the binding: the drives' CiA 402 status words and the fieldbus
frame (cycle counter, working counter) reach the C++ raw, and the core decodes and
supervises them (design page §2 "Drive status words", "Fieldbus watchdog")."""

import pytest

from safestate import _core as core

POSE = [0.0, -1.2, 1.1, -1.4, -1.57, 0.0]
OPERATION_ENABLED = 0x0037
FAULT = 0x0008


def inputs(words, counter, wkc=18):
    return {
        "estop_closed_a": True, "estop_closed_b": True,
        "safeguard_closed_a": True, "safeguard_closed_b": True,
        "enabling_a": "RELEASED", "enabling_b": "RELEASED", "selector_auto": True,
        "self_test_ok": True, "operator_link_ok": True, "q": POSE, "qd": [0.0] * 6,
        "drive_status_words": words, "fieldbus_cycle_counter": counter, "working_counter": wkc,
    }


def manager():
    return core.Manager(core.Config(tool_offset_m=(0.0, 0.0, 0.0)))


@pytest.mark.req("RSM-07")
def test_raw_status_words_arm_the_drives_and_a_fault_word_locks_out():
    m = manager()
    m.cycle(inputs([0x0031] * 6, 1))
    assert m.submit("SERVO_ON") == "QUEUED"
    m.cycle(inputs([0x0031] * 6, 2))
    assert m.observe()["state"] == "ARMING"
    m.cycle(inputs([OPERATION_ENABLED] * 6, 3))
    assert m.observe()["state"] == "AUTO_IDLE"
    assert m.drive_status()["states"] == ["OPERATION_ENABLED"] * 6
    m.cycle(inputs([OPERATION_ENABLED] * 5 + [FAULT], 4))
    obs = m.observe()
    assert obs["fault_code"] == "DRIVE_FAULT" and not obs["contactor_closed"]
    assert m.drive_status()["states"][5] == "FAULT"


def test_a_stalled_frame_counter_is_a_fieldbus_loss_computed_in_the_core():
    m = manager()
    m.cycle(inputs([0x0031] * 6, 7))
    assert m.observe()["state"] == "IDLE" and m.drive_status()["fieldbus_healthy"]
    m.cycle(inputs([0x0031] * 6, 7))
    assert m.observe()["fault_code"] == "FIELDBUS_LOSS"
    assert not m.drive_status()["fieldbus_healthy"]


def test_a_wrong_working_counter_is_a_fieldbus_loss():
    m = manager()
    m.cycle(inputs([0x0031] * 6, 1))
    m.cycle(inputs([0x0031] * 6, 2, wkc=15))
    assert m.observe()["fault_code"] == "FIELDBUS_LOSS"


def test_raw_bus_keys_and_abstract_levels_cannot_be_mixed():
    m = manager()
    bad = inputs([0x0031] * 6, 1)
    bad["servo_ready"] = True
    with pytest.raises(ValueError, match="not both"):
        m.cycle(bad)
    with pytest.raises(ValueError, match="6 ints"):
        m.cycle(inputs([0x0031] * 5, 1))
