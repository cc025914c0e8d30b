"""The compact replay plan (conform/replay_plan.py, the binding's PlanReplayer): the C++
walk compares every step's observe line, every checked step's fired rows and a submit's
QUEUE_FULL answer with the model's, reports the first disagreeing (trace, step), and the
plan is cached on disk.  On a seeded 300-step walk of the flagship (no exploration)."""

import os
import random
from array import array
from pathlib import Path

import pytest

from safestate.checker.model import load_model
from safestate.conform import conformance, replay_plan
from safestate.conform.cli import make_harness
from safestate.conform.graph import StateGraph
from safestate.conform.traces import ConcreteTrace, Step
from safestate.systems.registry import find, load_all

REPO = Path(__file__).resolve().parents[2]
STEPS = 300
# Every registered system whose adapter and binding replay as a plan.
PLAN_SYSTEMS = ["SystemStateManager", "SafetyService", "RuntimeSupervisor"]


def seeded_walk(name: str, steps: int = STEPS):
    """(harness, [the walk, its first half]) of a seeded random walk of the system's model."""
    system = find(name, REPO / "systems")
    model = load_model(str(system.model), str(system.conformance.config or system.ci_config))
    h = make_harness(system, model)
    rng = random.Random(7)
    state = model.initial_states()[0]
    walk = []
    for i in range(steps):
        event, state = rng.choice(h.stepper.transitions(state))
        walk.append(Step(event, state, i))  # edge ids: each step a transition of its own
    start = model.initial_states()[0]
    return h, [ConcreteTrace(start, walk), ConcreteTrace(start, walk[:steps // 2])]


@pytest.fixture(scope="module")
def walk():
    return seeded_walk("SystemStateManager")


def test_every_registered_system_with_a_plan_replay_is_listed():
    with_plan = []
    for s in load_all(REPO / "systems"):
        if s.conformance is None:
            continue
        model = load_model(str(s.model), str(s.conformance.config or s.ci_config))
        if make_harness(s, model).adapter.has_plan_replay():
            with_plan.append(s.name)
    assert sorted(with_plan) == sorted(PLAN_SYSTEMS)


@pytest.mark.parametrize("name", PLAN_SYSTEMS)
def test_plan_replay_agrees_with_step_by_step_replay_on_a_walk(name):
    """The binding's PlanReplayer and the adapter's apply/observe agree with the model on
    the same walk (the expected lines are the binding's own observe lines)."""
    h, traces = seeded_walk(name, 200)
    for ct in traces:
        mm, n = conformance.replay_trace(h, ct)
        assert mm is None and n == len(ct.steps)
    plan = replay_plan.build(h.adapter, traces)
    assert replay_plan.replayer(h.adapter, plan).run(0, 2) == (-1, -1)
    # and a wrong expected line after the last step is caught there
    plan.lines.append("not an observe line|")
    plan.aux.append(0)
    plan.exp_ids[len(plan.exp_ids) - 1] = len(plan.lines) - 1
    assert replay_plan.replayer(h.adapter, plan).run(0, 2) == (1, len(traces[1].steps) - 1)


def test_plan_replay_agrees_with_the_model_on_a_walk(walk):
    h, traces = walk
    plan = replay_plan.build(h.adapter, traces)
    assert plan.traces == 2 and plan.steps_in(0, 2) == STEPS + STEPS // 2
    assert len(plan.rows_at) > 0  # the walk's cycles have their rows checked
    assert replay_plan.replayer(h.adapter, plan).run(0, 2) == (-1, -1)


def test_plan_replay_reports_the_first_step_whose_observe_line_differs(walk):
    h, traces = walk
    plan = replay_plan.build(h.adapter, traces)
    k = 40
    plan.lines[plan.exp_ids[k]] = plan.lines[plan.exp_ids[k]].replace("|", "#", 1)
    first = min(i for i, e in enumerate(plan.exp_ids) if e == plan.exp_ids[k])
    assert replay_plan.replayer(h.adapter, plan).run(0, 2) == (0, first)


def test_plan_replay_compares_the_fired_rows(walk):
    h, traces = walk
    plan = replay_plan.build(h.adapter, traces)
    plan.row_lines.append("K99|")
    plan.rows_exp[3] = len(plan.row_lines) - 1
    assert replay_plan.replayer(h.adapter, plan).run(0, 2) == (0, plan.rows_at[3])


def test_plan_replay_checks_a_submits_queue_full_answer(walk):
    h, traces = walk
    plan = replay_plan.build(h.adapter, traces)
    submits = [i for i, c in enumerate(plan.call_ids) if plan.events[c].action == "Submit"]
    assert submits, "the walk submits no command"
    i = submits[0]
    before = plan.exp_ids[i - 1] if i > 0 else plan.initial_ids[0]
    plan.aux[before] ^= 1  # the model's queue now 'is' (not) full before that submit
    bad = replay_plan.replayer(h.adapter, plan).run(0, 2)
    assert bad[0] == 0 and bad[1] <= i


def test_a_malformed_plan_is_a_clear_error(walk):
    h, traces = walk
    plan = replay_plan.build(h.adapter, traces)
    plan.exp_ids.append(0)
    with pytest.raises(ValueError, match="call_ids and exp_ids differ"):
        replay_plan.replayer(h.adapter, plan)
    plan = replay_plan.build(h.adapter, traces)
    plan.call_ids[0] = len(plan.events)
    with pytest.raises(ValueError, match="call id is out of range"):
        replay_plan.replayer(h.adapter, plan).run(0, 1)


def test_plan_is_built_once_then_read_from_the_disk_cache(walk, tmp_path, monkeypatch):
    h, traces = walk
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path))
    graph = StateGraph([], [0], list(range(STEPS)), list(range(1, STEPS + 1)), [])
    built = []

    def traces_once():
        built.append(1)
        yield from traces
    first = replay_plan.cached_build(h.adapter, graph, traces_once(), "test", True)
    again = replay_plan.cached_build(h.adapter, graph, traces_once(), "test", True)
    assert built == [1]
    assert again.lines == first.lines and again.call_ids == first.call_ids
    assert len(list(tmp_path.glob("SystemStateManager-plan-*.pickle"))) == 1
    other = replay_plan.cached_build(h.adapter, graph, iter(traces), "other options", True)
    assert other.lines == first.lines
    assert len(list(tmp_path.glob("SystemStateManager-plan-*.pickle"))) == 2
    assert isinstance(again.call_ids, array)


def test_the_cache_folder_keeps_within_its_size_bound_dropping_the_least_recently_used(tmp_path, monkeypatch):
    """Every checker commit gives new keys: without a bound the cache only grows."""
    from safestate.conform import graph as graph_mod
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv(graph_mod.CACHE_MAX_ENV, "1")  # 1 MiB
    blob = b"x" * (400 * 1024)
    for i, name in enumerate(["old", "used", "newer"]):
        (tmp_path / f"{name}.pickle").write_bytes(blob)
        (tmp_path / f"{name}.lock").write_bytes(b"")
        os.utime(tmp_path / f"{name}.pickle", (1000 + i, 1000 + i))
    assert graph_mod._read_cached(tmp_path / "used.pickle", bytes, "blob", None) is None  # not a pickle, but...
    graph_mod.cached_pickle(tmp_path / "used.pickle", bytes, lambda: blob, "blob")  # ... rebuilt: read again is a use
    assert graph_mod._read_cached(tmp_path / "used.pickle", bytes, "blob", None) == blob
    graph_mod.cached_pickle(tmp_path / "new.pickle", bytes, lambda: blob, "blob")
    left = sorted(p.name for p in tmp_path.glob("*.pickle"))
    assert left == ["new.pickle", "used.pickle"]  # 'old' and then 'newer' (older than the read of 'used') dropped
    assert not (tmp_path / "old.lock").exists() and not (tmp_path / "newer.lock").exists()
