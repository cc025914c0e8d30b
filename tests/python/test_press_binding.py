"""SCH-05 through the pybind11 binding safestate._press (docs/design/hydraulic-press.md §7):
the flat C++ (defective reference) against HydraulicPressFlat.tla on every reachable
transition of the model's state graph, and the flat model's counterexample replayed through
both C++ presses: the flat one energises the stroke valve at the restart, the chain one not."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import REPO, run_safestate

press = pytest.importorskip("safestate._press")
MODELS = REPO / "models"


def _value(v: object) -> object:
    if isinstance(v, dict) and "#bigint" in v:
        return int(v["#bigint"])
    if isinstance(v, dict) and "#set" in v:
        return sorted(v["#set"])
    return v


def _projection(state: dict) -> dict:
    """The model state as observe() names it: motor, mode, step, outputs."""
    steps = ["Ready", "Feed", "Locate", "Clamp", "FastAdvance", "Pressing", "Blow", "Eject", "ClearScrap"]
    return {"motor": state["MoToOut"], "mode": _value(state["FangShi"]), "step": steps[int(_value(state["cur"]))],
            "outputs": _value(state["outputs"])}


def test_SCH05_flat_cpp_conforms_to_the_flat_model_on_every_reachable_transition(tmp_path: Path) -> None:
    graph_file = tmp_path / "graph.json"
    proc = run_safestate("check", str(MODELS / "HydraulicPressFlat.tla"), "--graph", str(graph_file))
    assert "Traceback" not in proc.stderr, proc.stderr
    graph = json.loads(graph_file.read_text())
    states = {s["id"]: s["state"] for s in graph["states"]}
    path: dict[int, list[str]] = {i: [] for i in graph["initial"]}  # BFS: events reaching each state
    for e in graph["edges"]:
        path.setdefault(e["to"], path[e["from"]] + [e["params"]["e"]])
    replayed = 0
    for e in graph["edges"]:
        p = press.PressFlat()
        for event in path[e["from"]] + [e["params"]["e"]]:
            p.cycle(event)
        assert p.observe() == _projection(states[e["to"]]), (path[e["from"]], e["params"]["e"])
        replayed += 1
    assert replayed == len(graph["edges"]) > 0


def test_SCH05_counterexample_replays_dangerous_through_flat_cpp_and_safe_through_chain() -> None:
    itf = json.loads((MODELS / "traces" / "HydraulicPressFlat_INV_PRESS.itf.json").read_text())
    events = [s["event"] for s in itf["states"]][1:]
    flat, chain = press.PressFlat(), press.HydraulicPress()
    for event in events:
        flat.cycle(event)
        chain.cycle(event)
    assert flat.observe()["step"] == "Feed" and "feed_valve" in flat.observe()["outputs"]
    assert chain.observe()["step"] == "Ready"
    assert not set(chain.observe()["outputs"]) & {"feed_valve", "press_valve", "clamp_valve"}


def test_unknown_press_event_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="unknown press input event 'bogus'"):
        press.HydraulicPress().cycle("bogus")
