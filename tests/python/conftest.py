"""Shared pytest fixtures (docs/testing.md): small modules for the checker tests, the CLI
in a subprocess, and `state_graph`, a model's explored state graph shared by every test
of a session (explore a model at most once per model, cfg and checker version)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from cost_record import pytest_runtest_protocol  # noqa: F401 - SAFESTATE_TEST_COSTS=FILE records each test's cost

REPO = Path(__file__).resolve().parents[2]
PYTHON_DIR = REPO / "python"
if str(PYTHON_DIR) not in sys.path:
    sys.path.insert(0, str(PYTHON_DIR))

CORPUS = REPO / "tests" / "tla" / "corpus"
ERRORS = REPO / "tests" / "tla" / "errors"


def load_expected(folder: Path) -> dict:
    path = folder / "expected.json"
    return json.loads(path.read_text()) if path.exists() else {}


def fair_lasso(model, r) -> tuple[list[tuple], list[tuple], list[tuple[tuple, tuple]]]:  # noqa: ANN001
    """Asserts that the liveness counterexample of result `r` is a behaviour of `model`
    (initial state, steps, the step back into the loop) and fair under its WF/SF;
    returns its states, the loop's states and the loop's steps (none if it stutters)."""
    assert r.trace is not None and r.loop is not None
    states = [s.state for s in r.trace]
    assert states[0] in model.initial_states()
    for a, b in zip(states, states[1:]):
        assert b in [t.state for t in model.successors(a)]
    cycle = states[r.loop:]
    if r.loop_step is None:
        steps: list[tuple[tuple, tuple]] = []
        assert r.loop == len(states) - 1
    else:
        assert r.loop_step.state == states[r.loop]
        assert states[r.loop] in [t.state for t in model.successors(states[-1])]
        steps = list(zip(cycle, cycle[1:])) + [(states[-1], states[r.loop])]
    for f in model.fairness:
        taken = any(f.taken(s, t) for s, t in steps)
        enabled = [f.enabled(s) for s in cycle]
        if f.kind == "WF":
            assert taken or not all(enabled), f"unfair: WF at {f.loc} enabled on the whole cycle, never taken"
        else:
            assert taken or not any(enabled), f"unfair: SF at {f.loc} enabled on the cycle, never taken"
    return states, cycle, steps


def run_safestate(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """Run the `safestate` CLI in a subprocess (as a user would)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = str(PYTHON_DIR) + os.pathsep + env.get("PYTHONPATH", "")
    return subprocess.run([sys.executable, "-m", "safestate.cli", *args], capture_output=True, text=True,
                          cwd=cwd, env=env, timeout=600)


@pytest.fixture(scope="session")
def state_graph():
    """state_graph(tla, cfg=None) -> (Model, StateGraph): the reachable state graph of a
    model under a cfg (its default .cfg when None).  Explored at most once: kept in memory
    for the session, and on disk across sessions and pytest-xdist workers
    (`conform.graph.cached_explore`, keyed by a hash of the model, the cfg and the
    checker's sources; $SAFESTATE_CACHE_DIR).  Use it instead of running `safestate check`
    on the same model again when a test only needs the reachable states or transitions."""
    from safestate.checker.model import load_model
    from safestate.conform.graph import cached_explore

    memo: dict[tuple[str, str | None], tuple] = {}

    def get(tla: Path | str, cfg: Path | str | None = None) -> tuple:
        key = (str(tla), None if cfg is None else str(cfg))
        if key not in memo:
            model = load_model(*key)
            memo[key] = (model, cached_explore(model))
        return memo[key]
    return get


@pytest.fixture
def tla_dir(tmp_path: Path):
    """Write small modules: tla_dir("Name", tla_text, cfg_text) -> path of Name.tla."""
    def write(name: str, tla: str, cfg: str | None = None) -> Path:
        (tmp_path / f"{name}.tla").write_text(tla)
        if cfg is not None:
            (tmp_path / f"{name}.cfg").write_text(cfg)
        return tmp_path / f"{name}.tla"
    return write


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config: pytest.Config, log):  # type: ignore[no-untyped-def]
    """`--dist loadfile` (the test command) schedules the longest work first and spreads
    the independent model-mutant checks over the workers (cost_schedule.py)."""
    if config.getvalue("dist") != "loadfile":
        return None
    from cost_schedule import CostOrderedFileScheduling
    return CostOrderedFileScheduling(config, log)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """A `@pytest.mark.req("ID")` names a requirement of REQUIREMENTS.md (when it is found):
    an unknown or missing ID fails the collection instead of linking the test to nothing."""
    from safestate.evidence.build import find_requirements
    from safestate.evidence.sources import read_requirements
    marked = [(i, m) for i in items for m in i.iter_markers("req")]
    path = find_requirements(REPO)
    if not marked or path is None:
        return
    known = {r.id for r in read_requirements(path, REPO)}
    for item, mark in marked:
        bad = [a for a in mark.args if a not in known] if mark.args else ["(no ID)"]
        if bad:
            raise pytest.UsageError(f"{item.nodeid}: @pytest.mark.req: {', '.join(map(str, bad))} is not a "
                                    "requirement ID of REQUIREMENTS.md")
