"""The pybind11 binding safestate._core: the C++ SystemStateManager driven from Python,
with the names and keys the conformance harness relies on (design page §2, §6, §7)."""

import json

import pytest

from safestate import _core as core

POSE = [0.0, -1.2, 1.1, -1.4, -1.57, 0.0]
REST = [0.0] * 6
SLOW = [0.05, 0, 0, 0, 0, 0]
FAST = [2.0, 0, 0, 0, 0, 0]  # above the T2 limit (1000 mm/s) at POSE
MEDIUM = [1.0, 0, 0, 0, 0, 0]  # between the T1 and the T2 limit

STATUS_KEYS = {
    "state", "selector", "session_mode", "stop_category", "fault_code", "last_reject_reason",
    "command_result", "estop_mismatch", "safeguard_mismatch", "enabling_mismatch",
    "selector_invalid", "state_cycles", "t2_confirmed", "resume_to", "jog_axis",
    "jog_direction", "jog_speed_mm_s", "queue_length",
    "stale_commands", "estop_tested_a", "estop_tested_b",  # K36, K37 (issue 17)
    "enable_release_required",  # K39 (issue 29)
    "contactor_fb_cycles", "brake_fb_cycles",  # C30 (issue 29 item 10)
}
OUTPUT_KEYS = {
    "contactor_closed", "drive_enable", "brake_release", "ramp_down_request", "reset_lamp",
    "commanded_speed_mm_s", "axes",
}


def healthy(mode="AUTO", **overrides):
    """Every input healthy in `mode` ('AUTO', 'T1', 'T2'); keyword arguments override."""
    manual = mode in ("T1", "T2")
    inputs = {
        "estop_closed_a": True, "estop_closed_b": True,
        "safeguard_closed_a": True, "safeguard_closed_b": True,
        "enabling_a": "MIDDLE" if manual else "RELEASED",
        "enabling_b": "MIDDLE" if manual else "RELEASED",
        "selector_auto": mode == "AUTO", "selector_t1": mode == "T1", "selector_t2": mode == "T2",
        "self_test_ok": True, "servo_ready": True, "drive_fault": False, "fieldbus_ok": True, "operator_link_ok": True,
        "q": POSE, "qd": REST,
    }
    inputs.update(overrides)
    return inputs


def flange_config(**fields):
    """The design-page defaults with the tool stated (a tool-less flange), as a Config must."""
    return core.Config(tool_offset_m=(0.0, 0.0, 0.0), **fields)


def command(manager, kind, inputs, **args):
    assert manager.submit(kind, **args) == "QUEUED"
    manager.cycle(inputs)
    return manager.observe()["command_result"]


def operational(mode="AUTO"):
    m = core.Manager(flange_config())
    m.cycle(healthy(mode))
    if mode == "T2":
        assert command(m, "T2_CONFIRM", healthy(mode)) == "ACCEPTED"
    assert command(m, "SERVO_ON", healthy(mode, servo_ready=False)) == "ACCEPTED"
    m.cycle(healthy(mode))
    return m


def test_module_and_api_are_documented():
    assert core.__doc__
    for obj in (core.Manager, core.Manager.cycle, core.Manager.submit, core.Manager.observe,
                core.Manager.last_rows, core.Config, core.transition_table, core.speed_level,
                core.tcp_speed_mm_s, core.transition_table_json, core.transition_table_dot):
        assert obj.__doc__, obj


def test_observe_has_exactly_the_status_and_output_keys_before_the_first_cycle():
    m = core.Manager(flange_config())
    obs = m.observe()
    assert set(obs) == STATUS_KEYS | OUTPUT_KEYS
    assert obs["state"] == "BOOT"
    assert obs["selector"] == "INVALID"
    assert obs["command_result"] == "NONE"
    assert obs["axes"] == ["Disabled"] * 6
    assert not obs["contactor_closed"]
    assert m.last_rows() == {"cycle": None, "command": None}


def test_cycle_returns_the_outputs():
    m = core.Manager(flange_config())
    out = m.cycle(healthy())
    assert set(out) == OUTPUT_KEYS
    assert m.observe()["state"] == "IDLE"
    assert m.last_rows() == {"cycle": "C05", "command": None}


def test_missing_inputs_take_the_safe_value():
    m = core.Manager(flange_config())
    m.cycle({})  # self-test not passed, E-stop open, ...
    obs = m.observe()
    assert obs["state"] == "ERROR_LOCKOUT"
    assert obs["fault_code"] == "SELF_TEST_FAILED"
    assert obs["stop_category"] == "CAT0"


def test_estop_release_needs_reset_rsm05():
    m = core.Manager(flange_config())
    m.cycle(healthy(estop_closed_b=False))
    assert m.observe()["state"] == "ESTOP_ACTIVE"
    assert command(m, "RESET", healthy(estop_closed_a=False, estop_closed_b=False)) == "ESTOP_PRESSED"
    assert m.last_rows() == {"cycle": "C08", "command": "K02"}
    assert m.observe()["estop_tested_a"] and m.observe()["estop_tested_b"]  # K37: both seen open
    m.cycle(healthy())
    obs = m.observe()
    assert obs["state"] == "ESTOP_RESET_NEEDED" and obs["reset_lamp"]
    assert obs["last_reject_reason"] == "ESTOP_PRESSED"
    assert command(m, "RESET", healthy()) == "ACCEPTED"
    assert m.observe()["state"] == "IDLE"


def test_servo_on_start_and_gate_open_cat1_rsm08():
    m = operational("AUTO")
    assert m.observe()["state"] == "AUTO_IDLE"
    assert command(m, "START", healthy()) == "ACCEPTED"
    assert m.observe()["axes"] == ["SynchronizedMotion"] * 6
    m.cycle(healthy(qd=SLOW, safeguard_closed_a=False))
    obs = m.observe()
    assert (obs["state"], obs["stop_category"], obs["ramp_down_request"]) == ("STOPPING", "CAT1", True)
    m.cycle(healthy(safeguard_closed_a=False))
    assert m.observe()["state"] == "IDLE"


def test_jog_speed_is_clamped_in_t1_and_overspeed_locks_out_rsm10():
    m = operational("T1")
    assert command(m, "JOG_START", healthy("T1"), axis=3, direction=-1, speed_mm_s=900) == "ACCEPTED"
    obs = m.observe()
    assert (obs["state"], obs["jog_axis"], obs["jog_direction"], obs["jog_speed_mm_s"]) == (
        "MANUAL_JOGGING", 3, -1, 250)
    assert obs["commanded_speed_mm_s"] == 250
    m.cycle(healthy("T1", qd=FAST))
    obs = m.observe()
    assert (obs["state"], obs["fault_code"], obs["contactor_closed"]) == ("ERROR_LOCKOUT", "T1_OVERSPEED", False)
    assert m.derived_inputs()["speed"] == "OVER_T2"  # FAST is above the T2 limit too: C10's in T1


@pytest.mark.req("RSM-08", "INV-NOJOG-AUTO")
def test_jog_in_auto_is_rejected_and_changes_nothing():
    m = operational("AUTO")
    before = m.observe()
    assert command(m, "JOG_START", healthy(), axis=1, direction=1, speed_mm_s=10) == "JOG_IN_AUTO"
    after = m.observe()
    for key in ("command_result", "last_reject_reason"):
        before.pop(key), after.pop(key)
    assert after == before


def test_full_queue_is_rejected_at_once_rsm14():
    m = core.Manager(flange_config(command_queue_limit=2))
    assert m.submit("RESET") == "QUEUED"
    assert m.submit("RESET") == "QUEUED"
    assert m.submit("SERVO_ON") == "QUEUE_FULL"
    obs = m.observe()
    assert obs["queue_length"] == 2
    assert obs["last_reject_reason"] == "QUEUE_FULL"
    assert obs["command_result"] == "NONE"


def test_bad_arguments_raise():
    m = core.Manager(flange_config())
    with pytest.raises(KeyError):
        m.cycle({"estop_a": True})
    with pytest.raises(ValueError):
        m.cycle({"enabling_a": "HALF"})
    with pytest.raises(TypeError):
        m.cycle({"enabling_a": 1})
    with pytest.raises(ValueError):
        m.cycle({"q": [0.0] * 5})
    with pytest.raises(ValueError):
        m.submit("LAUNCH")
    assert m.observe()["state"] == "BOOT"  # nothing ran


def test_transition_table_lists_c01_to_c30_and_k01_to_k39_and_matches_json_and_dot():
    rows = core.transition_table()
    ids = [r["id"] for r in rows]
    assert sorted(i for i in ids if i[0] == "C") == [f"C{i:02d}" for i in range(1, 31)]
    assert sorted(i for i in ids if i[0] == "K") == [f"K{i:02d}" for i in range(1, 40)]
    # issue 29: the latching rows before the E-stop's C06, C28 before C19, K39 after K10
    assert ids.index("C09") < ids.index("C27") < ids.index("C10") < ids.index("C25") < ids.index("C06")
    assert ids[ids.index("C28") + 1] == "C19" and ids[ids.index("K10") + 1] == "K39"
    # rows added by issues 17 and 16 sit where first-match needs them
    assert ids[3] == "C24" and ids[ids.index("K02") + 1] == "K36" and ids[ids.index("K06") + 1] == "K38"
    assert ids[ids.index("C14") + 1] == "C26"
    assert all(r["reason"] != "NONE" for r in rows if r["kind"] == "REJECT")
    k05 = rows[ids.index("K05")]
    assert k05["effective_source"] == ["ESTOP_RESET_NEEDED"] and k05["targets"] == ["IDLE"]
    assert k05["requirements"] == ["RSM-05", "INV-RESET"]
    doc = json.loads(core.transition_table_json())
    assert doc["rows"] == rows
    dot = core.transition_table_dot()
    assert dot.startswith("digraph")
    assert all(f"{i} " in dot for i in ids)


def test_speed_level_and_tcp_speed():
    assert core.speed_level(POSE, REST) == "ZERO"
    assert core.speed_level(POSE, SLOW) == "MOVING"
    assert core.speed_level(POSE, FAST) == "OVER_T2"
    assert core.speed_level(POSE, MEDIUM) == "OVER_T1"
    assert core.tcp_speed_mm_s(POSE, REST) == 0.0
    assert 0.0 < core.tcp_speed_mm_s(POSE, SLOW) < 250.0 < core.tcp_speed_mm_s(POSE, FAST)
    slow_limit = core.Config(t1_speed_limit_mm_s=10)
    assert core.speed_level(POSE, SLOW, slow_limit) == "OVER_T1"


def test_config_fields_are_read_write():
    c = core.Config()
    assert c.tool_offset_m is None and c.validate() == "TOOL_OFFSET_NOT_GIVEN"  # issue 29 item 4
    c.tool_offset_m = (0.0, 0.0, 0.1)
    assert c.tool_offset_m == (0.0, 0.0, 0.1)
    assert (c.cycle_time_us, c.discrepancy_cycles, c.arming_timeout_cycles, c.max_stop_cycles,
            c.t1_speed_limit_mm_s, c.zero_velocity_rad_s, c.command_queue_limit) == (
        1000, 50, 500, 1000, 250, 0.001, 8)
    assert len(c.dh) == 6 and c.dh[1][0] == pytest.approx(-0.425)
    c.discrepancy_cycles = 3
    c.arming_timeout_cycles = 4
    c.max_stop_cycles = 5
    c.t1_speed_limit_mm_s = 100
    c.zero_velocity_rad_s = 0.0015  # seen at the tool: inside the 10 mm/s standstill window
    c.command_queue_limit = 16
    c.cycle_time_us = 500
    dh = c.dh
    dh[5] = (0.0, 0.0, 0.2, 0.0)
    c.dh = dh
    assert c.dh[5] == (0.0, 0.0, 0.2, 0.0)
    assert c.validate() == "NONE"
    m = core.Manager(c)
    assert m.config.discrepancy_cycles == 3 and m.config_error == "NONE"
    c.command_queue_limit = 17
    assert c.validate() == "QUEUE_LIMIT_OUT_OF_RANGE"
    bad = core.Manager(c)
    bad.cycle(healthy())
    assert bad.observe()["fault_code"] == "SELF_TEST_FAILED"


@pytest.mark.req("RSM-04", "INV-DISCREPANCY")
def test_discrepancy_of_d_cycles_is_tolerated_and_d_plus_one_latches():
    m = core.Manager(flange_config(discrepancy_cycles=3))
    m.cycle(healthy())
    for _ in range(3):
        m.cycle(healthy(safeguard_closed_b=False))
    assert m.observe()["state"] == "IDLE"
    assert m.observe()["safeguard_mismatch"] == 3
    m.cycle(healthy(safeguard_closed_b=False))
    assert m.observe()["fault_code"] == "DISCREPANCY_SAFEGUARD"


def test_names_lists_every_enum():
    names = core.names()
    assert names["state"][0] == "BOOT" and len(names["state"]) == 12
    assert "QUEUE_FULL" in names["reject_reason"]
    assert names["speed_level"] == ["ZERO", "MOVING", "OVER_T1", "OVER_T2"]


def test_feedback_keys_default_to_the_last_outputs_and_a_welded_contactor_locks_out_uca_rsm_13():
    """Issue 29 item 10: without the feedback keys the devices follow their command (no
    fault however long the robot is powered); a contact reported closed while commanded
    open for more than feedback_allowed_cycles cycles is C30's CONTACTOR_FEEDBACK lockout."""
    m = operational("AUTO")
    for _ in range(150):
        m.cycle(healthy())
    assert m.observe()["state"] == "AUTO_IDLE"
    cfg = flange_config()
    cfg.feedback_allowed_cycles = 2
    w = core.Manager(cfg)
    for _ in range(2):  # the first cycle (BOOT -> IDLE) and one more: within the allowed 2
        w.cycle(dict(healthy(), contactor_feedback_closed=True))
        assert w.observe()["state"] == "IDLE"
    w.cycle(dict(healthy(), contactor_feedback_closed=True))
    obs = w.observe()
    assert (obs["state"], obs["fault_code"], obs["stop_category"]) == ("ERROR_LOCKOUT", "CONTACTOR_FEEDBACK", "CAT0")
    assert w.last_rows()["cycle"] == "C30"
