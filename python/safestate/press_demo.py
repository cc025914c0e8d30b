"""`safestate demo press`: the accident of the seed document, side by side (SCH-05).

The same operator inputs go through the flat defective reference (`PressFlat`) and the
chain press (`HydraulicPress`), both C++ through `safestate._press`; one line per scan
with the input, the flat press's step and outputs, the chain press's active states and
outputs.  A scan where a stroke output is energised right after a motor restart (motor
off -> on) is the accident: marked on the flat press's line.  The default inputs are the
counterexample `safestate check models/HydraulicPressFlat.tla` finds
(models/traces/HydraulicPressFlat_INV_PRESS.itf.json), then two more scans of the stroke.
"""

from __future__ import annotations

import json
from pathlib import Path
from types import ModuleType
from typing import Any

REPO = Path(__file__).resolve().parents[2]
TRACE = REPO / "models" / "traces" / "HydraulicPressFlat_INV_PRESS.itf.json"
STROKE_OUTPUTS = {"feed_valve", "locate_valve", "clamp_valve", "fast_valve", "press_valve", "blow_valve",
                  "eject_valve", "scrap_valve"}
# Shown of the chain press: the mode and the leaves; the structural states (the root, each
# mode's motor-on, stroke and aux states) are implied by them.
STRUCTURAL_SUFFIXES = ("_On", "_Stroke", "_Aux")


def shown(state: str) -> bool:
    """Whether the demo prints this active state of the chain press."""
    return state != "Press" and not state.endswith(STRUCTURAL_SUFFIXES)


def counterexample_events(trace: Path = TRACE) -> list[str]:
    """The input events of the flat model's counterexample (its ITF trace)."""
    states = json.loads(trace.read_text())["states"]
    return [s["event"] for s in states[1:]]


def accident(before: dict[str, Any], after: dict[str, Any]) -> bool:
    """A stroke output energised in the scan the motor came back on."""
    return not before["motor"] and after["motor"] and bool(STROKE_OUTPUTS & set(after["outputs"]))


def lines(press: ModuleType, events: list[str]) -> list[str]:
    """One line per scan: input | flat press | chain press, the accident marked."""
    flat, chain = press.PressFlat(), press.HydraulicPress()
    out = [f"{'scan':>4}  {'input':<14} | {'flat (DEFECTIVE REFERENCE)':<42} | chain press (active states) ",
           "-" * 120]
    for n, e in enumerate(events, 1):
        f0 = flat.observe()
        flat.cycle(e)
        chain.cycle(e)
        f, c = flat.observe(), chain.observe()
        active = [s for s in chain.active() if shown(s)]
        flat_col = f"step {f['step']:<11} out {','.join(f['outputs']) or '-'}"
        chain_col = f"{' > '.join(active):<38} out {','.join(c['outputs']) or '-'}"
        mark = "   <== ACCIDENT: restart energises a stroke output (flat)" if accident(f0, f) else ""
        if accident(f0, c):
            mark += "   <== the chain press too (a defect)"
        out.append(f"{n:>4}  {e:<14} | {flat_col:<42} | {chain_col}{mark}")
    return out


def run(events: list[str] | None = None) -> int:
    try:
        import safestate._press as press
    except ImportError as e:
        print(f"safestate demo press: the binding safestate._press is not built ({e}); run bash scripts/setup.sh")
        return 2
    evs = events if events else counterexample_events() + ["step_done", "step_done"]
    try:
        print("\n".join(lines(press, evs)))
    except ValueError as e:  # an unknown input event name, from the binding
        print(f"safestate demo press: {e}")
        return 2
    return 0
