"""Abstract model events -> calls of the C++ binding.

Cycle(in): the model's abstract inputs become raw channels (design §2): each channel
level is passed as is; selector AUTO/T1/T2 closes exactly that contact and INVALID
closes none; speed ZERO/MOVING/OVER_T1 becomes joint velocities at a fixed pose,
chosen once with the binding's own `tcp_speed_mm_s` / `speed_level` so that the C++
classifies each exactly as the model's level.
Submit(c): `manager.submit(kind, axis, direction, speed_mm_s)`.
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

from ..tla.values import Value

POSE = [0.0, -1.2, 1.1, -1.4, -1.57, 0.0]
# Constant name in the model -> Config field (design §9).
CONFIG_CONSTANTS = {
    "DiscrepancyCycles": "discrepancy_cycles",
    "ArmingTimeoutCycles": "arming_timeout_cycles",
    "MaxStopCycles": "max_stop_cycles",
    "T1SpeedLimit": "t1_speed_limit_mm_s",
    "QueueCapacity": "command_queue_limit",
}
SELECTOR_CONTACT = {"AUTO": "selector_auto", "T1": "selector_t1", "T2": "selector_t2"}


def make_config(core: ModuleType, constants: dict[str, int]) -> Any:
    return core.Config(**{CONFIG_CONSTANTS[k]: v for k, v in constants.items()})


def speed_vectors(core: ModuleType, config: Any) -> dict[str, list[float]]:
    """Joint velocities the C++ classifies as ZERO, MOVING and OVER_T1 (checked)."""
    unit = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    per_rad = core.tcp_speed_mm_s(POSE, unit, config)  # mm/s per rad/s of joint 1
    limit = float(config.t1_speed_limit_mm_s)
    moving = 0.5 * limit / per_rad
    if moving <= config.zero_velocity_rad_s:
        raise ValueError("T1 limit too small for a MOVING velocity above the zero threshold")
    out = {"ZERO": [0.0] * 6, "MOVING": [moving] + [0.0] * 5, "OVER_T1": [2.0 * limit / per_rad] + [0.0] * 5}
    for level, qd in out.items():
        got = core.speed_level(POSE, qd, config)
        if got != level:
            raise ValueError(f"speed vector for {level} classifies as {got}")
    return out


class InputMapper:
    def __init__(self, core: ModuleType, config: Any) -> None:
        self.speeds = speed_vectors(core, config)
        self._cache: dict[Value, dict[str, Any]] = {}

    def raw(self, rec: dict[str, Value], key: Value | None = None) -> dict[str, Any]:
        """The ScanInputs dict for the model's abstract input record `rec`."""
        if key is not None and key in self._cache:
            return self._cache[key]
        sel = rec["selector"]
        d = {
            "estop_closed_a": rec["estop_a"], "estop_closed_b": rec["estop_b"],
            "safeguard_closed_a": rec["gate_a"], "safeguard_closed_b": rec["gate_b"],
            "enabling_a": rec["enable_a"], "enabling_b": rec["enable_b"],
            "selector_auto": sel == "AUTO", "selector_t1": sel == "T1", "selector_t2": sel == "T2",
            "self_test_ok": rec["self_test_ok"], "servo_ready": rec["servo_ready"],
            "drive_fault": rec["drive_fault"],
            # issue 17 (C24): the fieldbus/cycle watchdog input of ScanInputs.
            "fieldbus_ok": rec["fieldbus_ok"],
            "q": POSE, "qd": self.speeds[rec["speed"]],  # type: ignore[index]
        }
        if key is not None:
            self._cache[key] = d
        return d


def submit_args(rec: dict[str, Value]) -> tuple[str, int, int, int]:
    return (rec["kind"], rec["axis"], rec["direction"], rec["speed_mm_s"])  # type: ignore[return-value]
