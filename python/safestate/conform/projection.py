"""Projection of a model state onto what the C++ exposes through `observe()`.

The status record (design §7) is the model variable of the same name, `jog` is split
into jog_axis / jog_direction / jog_speed_mm_s, and the outputs are the model's own
output operators (contactor_closed, ..., commanded_speed_mm_s, queue_length),
evaluated by the checker.  History and environment variables (inputs, event, the
requirement observers obs_*, ...) are not observable and are left out.
"""

from __future__ import annotations

from typing import Any

from ..tla.values import FnValue, Value
from .model_step import ModelStepper

# observe() keys taken from a model variable of the same name.
STATUS_VARS = ("state", "selector", "session_mode", "stop_category", "fault_code", "last_reject_reason",
               "command_result", "estop_mismatch", "safeguard_mismatch", "enabling_mismatch",
               "selector_invalid", "state_cycles", "t2_confirmed", "resume_to",
               # issue 17: the Reset interlock (K36 stale commands, K37 channel test).
               "stale_commands", "estop_tested_a", "estop_tested_b")
# observe() keys computed by a model operator of the same name (§7 outputs).
OUTPUT_OPS = ("contactor_closed", "drive_enable", "brake_release", "ramp_down_request", "reset_lamp",
              "commanded_speed_mm_s", "queue_length")
JOG_FIELDS = (("jog_axis", "axis"), ("jog_direction", "direction"), ("jog_speed_mm_s", "speed_mm_s"))
KEYS = STATUS_VARS + tuple(k for k, _ in JOG_FIELDS) + OUTPUT_OPS + ("axes",)


def plain(v: Value) -> Any:
    """A model value as the plain Python value the binding returns."""
    if type(v) is tuple:
        return [plain(x) for x in v]
    if type(v) is FnValue:
        return {k: plain(x) for k, x in v.d.items()}  # type: ignore[union-attr]
    return v


class Projection:
    def __init__(self, stepper: ModelStepper) -> None:
        names = stepper.model.variables
        self.names = names
        self.index = {n: names.index(n) for n in STATUS_VARS + ("jog", "axes")}
        self.ops = [(k, stepper.definition(k)) for k in OUTPUT_OPS]

    def index_of(self, var: str) -> int:
        return self.names.index(var)

    def __call__(self, state: tuple) -> dict[str, Any]:
        out: dict[str, Any] = {k: plain(state[self.index[k]]) for k in STATUS_VARS}
        jog = state[self.index["jog"]].d  # type: ignore[union-attr]
        for key, field in JOG_FIELDS:
            out[key] = jog[field]
        for key, fn in self.ops:
            out[key] = plain(fn(state))
        out["axes"] = plain(state[self.index["axes"]])
        return out


def differing(model: dict[str, Any], cpp: dict[str, Any]) -> list[str]:
    """Keys whose values differ (a key missing on either side differs)."""
    keys = list(model) + [k for k in cpp if k not in model]
    return [k for k in keys if k not in model or k not in cpp or model[k] != cpp[k]]
