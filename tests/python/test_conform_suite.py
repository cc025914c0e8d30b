"""`safestate conform` on the CI configuration: the C++ agrees with the model on every
reachable transition and under Hypothesis lockstep testing, every table row is
taken, and a deliberately wrong C++ build is caught by both methods.

Slow (the model's state graph is explored once per session, ~1.5 min; the full
replay takes a few minutes).  Hypothesis: SAFESTATE_CONFORM_STEPS (default 10000)
and SAFESTATE_CONFORM_PROFILE=long for long runs.
"""

import os
import subprocess
from pathlib import Path

import pytest

from safestate.checker.model import load_model
from safestate.conform import audit as audit_mod
from safestate.conform import conformance, graph as graph_mod, itf_io
from safestate.conform.binding import load_core
from safestate.conform.cover import cover
from safestate.conform.lockstep import run_lockstep
from safestate.conform.model_step import ModelStepper
from safestate.conform.replay import Harness

REPO = Path(__file__).resolve().parents[2]
MODEL = str(REPO / "models" / "SystemStateManager.tla")
STEPS = int(os.environ.get("SAFESTATE_CONFORM_STEPS", "10000"))


@pytest.fixture(scope="module")
def model():
    return load_model(MODEL)


@pytest.fixture(scope="module")
def graph(model):
    return graph_mod.explore(model)


@pytest.fixture(scope="module")
def full_run(model, graph, tmp_path_factory):
    core = load_core("safestate._core")
    h = Harness(ModelStepper(model), core)
    out = tmp_path_factory.mktemp("conform")
    res = conformance.run(model, core, graph, h, conformance.Options(reproducer_dir=str(out)))
    return res, h, core


@pytest.fixture(scope="module")
def wrong_core(tmp_path_factory):
    build = tmp_path_factory.mktemp("wrong")
    subprocess.run([str(REPO / "conformance" / "wrong_variant" / "build.sh"), "wrong", str(build)],
                   check=True, capture_output=True)
    return load_core("safestate_wrong._core", str(build))


def test_whole_conformance_on_ci_cfg_has_no_mismatch_and_covers_every_transition(full_run):
    res, h, _ = full_run
    assert [f.mismatch.render() for f in res.found] == []
    assert res.transitions_covered == res.transitions_total > 0
    assert h.stats.row_checks >= res.transitions_total - h.stats.submits  # every Cycle transition's rows compared


def test_table_audit_every_row_taken_except_the_declared_unreachable(full_run):
    res, h, core = full_run
    a = audit_mod.audit(core, h.stats.rows)
    assert a.rows_missing == []
    assert a.unreachable_fired == [] and a.unknown_fired == []
    assert a.rows_unreachable == list(audit_mod.UNREACHABLE_BY_CONSTRUCTION)
    assert len(a.rows_taken) == a.rows_total - 4


def test_hypothesis_lockstep_agrees_for_at_least_10000_steps(model):
    h = Harness(ModelStepper(model), load_core("safestate._core"))
    steps, failure = run_lockstep(h, model, STEPS)
    assert failure is None
    assert steps >= STEPS


def test_trace_cover_is_deterministic(graph):
    g = graph.as_cover_graph()
    assert cover(g) == cover(g)


def test_wrong_variant_is_caught_by_trace_replay(model, graph, wrong_core, tmp_path):
    h = Harness(ModelStepper(model), wrong_core)
    res = conformance.run(model, wrong_core, graph, h,
                          conformance.Options(reproducer_dir=str(tmp_path), max_mismatches=1))
    assert len(res.found) == 1
    f = res.found[0]
    text = f.mismatch.render()
    print(text)
    assert "MISMATCH" in text
    # the reproducer replays to the same disagreement, and not on the right build
    ct = itf_io.read(f.reproducer, model)
    mm, n = conformance.replay_trace(h, ct)
    assert mm is not None and n == len(ct.steps) == f.reproducer_steps
    ok, _ = conformance.replay_trace(Harness(ModelStepper(model), load_core("safestate._core")), ct)
    assert ok is None


def test_wrong_variant_is_caught_by_hypothesis(model, wrong_core):
    h = Harness(ModelStepper(model), wrong_core)
    steps, failure = run_lockstep(h, model, 50 * STEPS)
    assert failure is not None, f"not caught in {steps} steps"
    print(failure)
    assert "MISMATCH" in failure
