"""The model side of conformance computed by the native core (conform/native_step.py):
for every registered system with a conformance adapter, on a deterministic sample of
reachable states (every k-th graph node and the concrete states along the first cover
traces), the core and the Python evaluator give the same transitions (events, order,
states, value kinds), edge successors, VIEW, projections, expected lines and fired rows;
the replay plan built with native stepping is the Python-built plan; an operator the
core refuses, or an evaluation error inside it, is answered by the Python evaluator."""

from __future__ import annotations

import pickle
from pathlib import Path

import pytest

from safestate.checker.model import load_model
from safestate.conform import graph as graph_mod
from safestate.conform import replay_plan
from safestate.conform.cli import make_harness
from safestate.conform.cover import Trace, bfs_tree, cover
from safestate.conform.model_step import STEP_ENGINE_ENV, ModelStepper
from safestate.conform.traces import Materializer
from safestate.systems.registry import find
from safestate.tla.errors import TlaError
from safestate.tla.values import FnValue

REPO = Path(__file__).resolve().parents[2]
SYSTEMS = ["SystemStateManager", "SafetyService", "RuntimeSupervisor", "Protection", "HydraulicPress",
           "HydraulicPressFlat"]
NODES = 40    # graph nodes sampled per system (every k-th)
TRACES = 150  # cover traces materialized per system
STEPS = 40    # steps of each


def shape(v):
    """A value with its kinds: equal shapes are equal values of the same Python types
    (True and 1, a tuple and a function over 1..n, differ)."""
    t = type(v)
    if t is tuple:
        return t, tuple(map(shape, v))
    if t is FnValue:
        return t, frozenset((shape(k), shape(x)) for k, x in v.d.items())
    if t is frozenset:
        return t, frozenset(map(shape, v))
    return t, v


def harnesses(system, model, monkeypatch):
    native = make_harness(system, model)
    with monkeypatch.context() as m:
        m.setenv(STEP_ENGINE_ENV, "python")
        python = make_harness(system, model)
    assert native.stepper.native is not None, native.stepper.engine_note
    assert python.stepper.native is None
    return native, python


def system_model(name):
    system = find(name, REPO / "systems")
    return system, load_model(str(system.model), str(system.conformance.config or system.ci_config))


_covers: dict[int, tuple] = {}


def first_traces(graph, n):
    """(BFS tree parents, the first n cover traces); the cover computed once per graph."""
    if id(graph) not in _covers:
        cg = graph.as_cover_graph()
        tree = bfs_tree(cg)
        _covers[id(graph)] = (graph, tree[0], cover(cg, tree=tree)[:max(n, 400)])
    _, parent, traces = _covers[id(graph)]
    return parent, traces[:n]


@pytest.mark.parametrize("name", SYSTEMS)
def test_native_stepping_agrees_with_python_on_sampled_states(name, state_graph, monkeypatch):
    system, _ = system_model(name)
    model, graph = state_graph(system.model, system.conformance.config or system.ci_config)
    nat, py = harnesses(system, model, monkeypatch)
    parent, traces = first_traces(graph, TRACES)
    traces = [Trace(t.start, t.edges[:STEPS]) for t in traces]  # a prefix of each (some are long)
    sample = graph.states[::max(1, len(graph.states) // NODES)]
    mats = [Materializer(h.stepper, graph) for h in (nat, py)]
    for m in mats:
        m.set_tree(parent)
    for t in traces:
        a, b = (m.trace(t) for m in mats)
        assert shape([s.state for s in a.steps]) == shape([s.state for s in b.steps])
        sample += [s.state for s in a.steps[-2:]]
    plan = nat.adapter.has_plan_replay()
    for state in sample:
        got, want = nat.stepper.transitions(state), py.stepper.transitions(state)
        assert [e for e, _ in got] == [e for e, _ in want]  # the same events, in the same order
        assert shape([s for _, s in got]) == shape([s for _, s in want])
        assert shape(nat.stepper.key(state)) == shape(py.stepper.key(state))
        assert shape(nat.adapter.project(state)) == shape(py.adapter.project(state))
        if plan:
            assert nat.adapter.expected_line(state) == py.adapter.expected_line(state)
        for ev, _ in want[:12]:
            assert shape(nat.stepper.edge_successor(state, ev)) == shape(py.stepper.edge_successor(state, ev))
            if nat.adapter.fires_rows(ev):
                assert nat.adapter.model_rows(state, ev) == py.adapter.model_rows(state, ev)
    # the core answered every call: none fell back to Python, and it was used at all
    assert nat.stepper.native.fallbacks == 0
    assert nat.stepper.native.calls > len(sample)


def test_replay_plan_built_natively_equals_the_python_built_plan(state_graph, monkeypatch):
    """On the flagship's first cover traces (the whole plan was compared once by hand)."""
    system, _ = system_model("SystemStateManager")
    model, graph = state_graph(system.model, system.conformance.config or system.ci_config)
    parent, traces = first_traces(graph, 250)
    plans = []
    for h in harnesses(system, model, monkeypatch):
        mat = Materializer(h.stepper, graph)
        mat.set_tree(parent)
        plans.append(replay_plan.build(h.adapter, (mat.trace(t) for t in traces)))
    nat, py = plans
    assert nat.traces == len(traces) and len(nat.rows_at) > 0
    assert pickle.dumps(vars(nat)) == pickle.dumps(vars(py))


REFUSED = """---- MODULE Refused ----
EXTENDS Naturals, Sequences
VARIABLES x, q
RECURSIVE Sum(_)
Sum(s) == IF s = <<>> THEN 0 ELSE Head(s) + Sum(Tail(s))
Total == Sum(q)
Front == Head(q)
Init == x = 0 /\\ q = <<>>
Next == x < 3 /\\ x' = x + 1 /\\ q' = Append(q, x + 1)
====
"""


def test_an_operator_the_core_refuses_is_evaluated_in_python(tla_dir):
    """Sum is recursive (outside the core's subset): Total falls back to Python and still
    answers; the step itself and Front stay in the core."""
    model = load_model(str(tla_dir("Refused", REFUSED, "INIT Init\nNEXT Next\n")))
    stepper = ModelStepper(model)
    assert stepper.native is not None
    state = model.initial_states()[0]
    for _ in range(3):
        (_, state), = stepper.transitions(state)
    assert stepper.definition("Total")(state) == 6
    assert stepper.native._nodes[("expr", "Total", ())] is None  # refused: Python answered
    calls = stepper.native.calls
    assert stepper.definition("Front")(state) == 1
    assert stepper.native.calls == calls + 1


def test_an_evaluation_error_in_the_core_is_reported_by_python(tla_dir):
    """Head(<<>>) fails inside the core; the user sees the Python engine's located error."""
    model = load_model(str(tla_dir("Refused", REFUSED, "INIT Init\nNEXT Next\n")))
    stepper = ModelStepper(model)
    state = model.initial_states()[0]
    with pytest.raises(TlaError) as native_err:
        stepper.definition("Front")(state)
    assert stepper.native.fallbacks == 1
    with pytest.raises(TlaError) as python_err:
        model.compiler.evaluator(model.scope.lookup("Front").defn.body, model.scope)(state, None)
    assert str(native_err.value) == str(python_err.value)
    assert "Refused.tla:7" in str(native_err.value)


def test_step_engine_python_forces_the_python_evaluator(tla_dir, monkeypatch):
    model = load_model(str(tla_dir("Refused", REFUSED, "INIT Init\nNEXT Next\n")))
    monkeypatch.setenv(STEP_ENGINE_ENV, "python")
    stepper = ModelStepper(model)
    assert stepper.native is None
    assert stepper.engine_note == f"the Python engine (${STEP_ENGINE_ENV}=python)"


def test_plan_key_changes_when_the_native_core_changes(state_graph, monkeypatch, tmp_path):
    system, _ = system_model("SafetyService")
    model, graph = state_graph(system.model, system.conformance.config or system.ci_config)
    h = make_harness(system, model)
    before = replay_plan.plan_key(h.adapter, graph, "")
    core = tmp_path / "tla_native_module.cpp"
    core.write_bytes(graph_mod.native_core_sources()[0].read_bytes() + b"// changed\n")
    monkeypatch.setattr(graph_mod, "native_core_sources", lambda: [core])
    assert replay_plan.plan_key(h.adapter, graph, "") != before


def test_value_ids_computed_in_python_are_the_cores():
    """Booleans and integers are tagged ids the bridge computes itself, strings are looked
    up once: the same ids the core's own constructors give."""
    from safestate import _tla_native
    from safestate.checker.native.values import ValueBridge
    engine = _tla_native.Engine()
    bridge = ValueBridge(engine)
    for v in (0, 1, -1, 7, (1 << 30) - 1, -(1 << 30)):
        assert bridge.to_native(v, None) == engine.mk_int(v)
    assert [bridge.to_native(b, None) for b in (False, True)] == [engine.mk_bool(False), engine.mk_bool(True)]
    assert bridge.to_native("AUTO", None) == bridge.to_native("AUTO", None) == engine.mk_str("AUTO", 0)
