"""The state graph of `conform/graph.py: explore()` built by the native core (issue 9):
wherever the core accepts a model, its graph must be the Python engine's, field by
field — the same states in the same order (equal values of the same types), the same
initial states, and the same edges (source, target, action and parameters) after
merging duplicates — and where it refuses, explore() falls back to the Python engine.
A change to the core's C++ source must change the graph cache key."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import CORPUS, REPO
from safestate.checker.itf import value_to_itf
from safestate.checker.model import load_model
from safestate.conform import graph as graph_mod
from safestate.conform.graph import NondeterministicEvent, StateGraph, explore, explore_python
from safestate.conform.native_graph import native_graph
from safestate.errors import SafestateError

REALWORLD = REPO / "tests" / "tla" / "realworld" / "specs"
MODELS = REPO / "models"

# Specs whose graph the core must build (so that the tests cannot pass by refusing).
# Models cheap for the Python engine only (the flagship's Python graph costs ~70 s: compared by hand).
MUST_ACCEPT = {
    CORPUS: ["AllAssigned", "Constraints", "DropParam", "JugPuzzle", "NaiveMutex", "RecordEnumeration", "SelectSeqTests",
             "TrafficView", "TwoPhase", "VendingMachine"],
    REALWORLD: ["DieHard", "DiningPhilosophers", "HourClock", "NestedExcept", "Peterson", "Semaphore", "TCommit"],
    MODELS: ["PLCopenAxis", "Protection"],
}


def _strict(v: object) -> str:
    """A value as ITF JSON: unlike ==, tells TRUE from 1 and a set from a sequence."""
    return json.dumps(value_to_itf(v), sort_keys=True)  # type: ignore[arg-type]


def _fields(g: StateGraph) -> tuple:
    return ([tuple(_strict(v) for v in s) for s in g.states], g.initial, g.src, g.dst,
            [(e.action, tuple((n, _strict(v)) for n, v in e.params)) for e in g.events])


def _specs(folder: Path) -> list[str]:
    return sorted(p.stem for p in folder.glob("*.tla") if p.with_suffix(".cfg").exists())


CASES = [(folder, name) for folder in (CORPUS, REALWORLD) for name in _specs(folder)] + \
        [(MODELS, name) for name in MUST_ACCEPT[MODELS]] + [(MODELS, "HydraulicPressFlat_conform")]


def _load(folder: Path, name: str):  # type: ignore[no-untyped-def]
    if name == "HydraulicPressFlat_conform":
        return load_model(str(folder / "HydraulicPressFlat.tla"), str(folder / f"{name}.cfg"))
    return load_model(str(folder / f"{name}.tla"))


def _graph_or_error(build, model) -> StateGraph | str:  # type: ignore[no-untyped-def]
    try:
        return build(model)
    except SafestateError as e:
        return f"{type(e).__name__}: {e}"


@pytest.mark.parametrize("folder,name", CASES, ids=[f"{f.name}/{n}" for f, n in CASES])
def test_native_state_graph_equals_the_python_engines_graph(folder: Path, name: str) -> None:
    try:
        model = _load(folder, name)
    except Exception:
        pytest.skip("the spec does not load (an error-reporting spec)")
    native = native_graph(model)
    if isinstance(native, str):
        assert name not in MUST_ACCEPT.get(folder, []), f"{name}: {native}"
        return
    notes: list[str] = []
    got = _graph_or_error(lambda m: explore(m, progress=notes.append), _load(folder, name))
    want = _graph_or_error(explore_python, _load(folder, name))
    if isinstance(want, str):
        assert got == want  # the same failure (a violation, a nondeterministic event, an error)
        return
    assert "conform: state graph built by the native engine" in notes
    assert isinstance(got, StateGraph)
    assert _fields(got) == _fields(want)


def test_must_accept_list_names_existing_specs() -> None:
    for folder, names in MUST_ACCEPT.items():
        for name in names:
            assert (folder / f"{name}.tla").exists() and (folder / f"{name}.cfg").exists(), name


NONDETERMINISTIC = """---- MODULE NonDet ----
EXTENDS Naturals
VARIABLE x
Init == x = 0
Step(i) == x' \\in {(x + i) % 3, (x + 2 * i) % 3}
Next == \\E i \\in {1} : Step(i)
====
"""

REFUSED = """---- MODULE Refused ----
EXTENDS Naturals
VARIABLE x
Init == x = {}
RECURSIVE Subsets(_)
Subsets(S) == IF S = {} THEN {{}}
              ELSE LET e == CHOOSE y \\in S : TRUE
                   IN Subsets(S \\ {e}) \\cup {t \\cup {e} : t \\in Subsets(S \\ {e})}
Next == \\E s \\in Subsets({1, 2}) : x' = s
====
"""


def test_nondeterministic_event_is_reported_by_both_engines_alike(tla_dir) -> None:  # type: ignore[no-untyped-def]
    tla = tla_dir("NonDet", NONDETERMINISTIC, "INIT Init\nNEXT Next\n")
    assert not isinstance(native_graph(load_model(str(tla))), str)
    with pytest.raises(NondeterministicEvent) as native:
        explore(load_model(str(tla)))
    with pytest.raises(NondeterministicEvent) as python:
        explore_python(load_model(str(tla)))
    assert str(native.value) == str(python.value)
    assert "event Step(1) leads to nodes" in str(native.value)


def test_a_model_outside_the_core_is_explored_by_the_python_engine(tla_dir) -> None:  # type: ignore[no-untyped-def]
    tla = tla_dir("Refused", REFUSED, "INIT Init\nNEXT Next\n")
    refusal = native_graph(load_model(str(tla)))
    assert isinstance(refusal, str) and "Refused.tla:9:" in refusal and "Subsets is not supported by the native engine" in refusal
    notes: list[str] = []
    g = explore(load_model(str(tla)), progress=notes.append)
    assert [n for n in notes if n.startswith("conform: state graph built by the Python engine")]
    assert set(g.states) == {(frozenset(),), (frozenset({1}),), (frozenset({2}),), (frozenset({1, 2}),)}
    assert g.initial == [0] and len(g.src) == 16


def test_a_change_to_the_native_core_changes_the_graph_cache_key(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Any file of the core, however it is split (here a second source beside the module)."""
    import safestate.checker.native as native_pkg
    core = tmp_path / "tla_native_module.cpp"
    core.write_text("// the core\n")
    part = tmp_path / "tla_native_values.cpp"
    part.write_text("// values\n")
    monkeypatch.setattr(native_pkg, "_BINDINGS", tmp_path)
    model = load_model(str(MODELS / "PLCopenAxis.tla"))
    before = graph_mod.graph_key(model)
    assert graph_mod.graph_key(model) == before
    core.write_text("// the core, changed\n")
    changed = graph_mod.graph_key(model)
    assert changed != before
    part.write_text("// values, changed\n")
    assert graph_mod.graph_key(model) != changed


def test_graph_engine_python_makes_the_python_engine_build_the_graph(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.setenv(graph_mod.GRAPH_ENGINE_ENV, "python")
    notes: list[str] = []
    g = explore(load_model(str(MODELS / "PLCopenAxis.tla")), progress=notes.append)
    assert "conform: state graph built by the Python engine ($SAFESTATE_GRAPH_ENGINE=python)" in notes
    assert len(g.states) == 104
