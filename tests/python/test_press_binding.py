"""SCH-05 through the pybind11 binding safestate._press (docs/design/hydraulic-press.md §7):
the flat C++ press against its model (HydraulicPressFlat.tla) on every reachable transition of
the model's state graph, and the flat model's counterexample replayed through both C++
presses: the flat one energises the stroke valve at the restart, the chain one not.  The
chain press's every reachable transition is replayed by the generic conformance
suite (tests/python/test_conform_suite.py, system HydraulicPress), on the cached graph,
its active set and call log included (tests/python/test_press_conform_observables.py)."""

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


def _replay_every_transition(model: str, make_press, projection, tmp_path: Path) -> int:
    """Every edge of the model's state graph: reach its source by the BFS path of input
    events, apply the edge's event, compare observe() with the target state."""
    graph_file = tmp_path / "graph.json"
    proc = run_safestate("check", str(MODELS / f"{model}.tla"), "--graph", str(graph_file))
    assert "Traceback" not in proc.stderr, proc.stderr
    graph = json.loads(graph_file.read_text())
    states = {s["id"]: s["state"] for s in graph["states"]}
    path: dict[int, list[str]] = {i: [] for i in graph["initial"]}
    for e in graph["edges"]:
        path.setdefault(e["to"], path[e["from"]] + [e["params"]["e"]])
    for e in graph["edges"]:
        p = make_press()
        for event in path[e["from"]] + [e["params"]["e"]]:
            p.cycle(event)
        assert p.observe() == projection(states[e["to"]]), (path[e["from"]], e["params"]["e"])
    return len(graph["edges"])


def test_SCH05_flat_cpp_conforms_to_the_flat_model_on_every_reachable_transition(tmp_path: Path) -> None:
    assert _replay_every_transition("HydraulicPressFlat", press.PressFlat, _projection, tmp_path) == 421


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
