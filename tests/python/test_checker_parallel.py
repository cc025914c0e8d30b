"""`safestate check --workers 2`: the fingerprint space sharded over two worker processes
(checker/parallel.py, checker/shard_worker.py) gives exactly the single worker's result —
verdict, distinct/generated counts, depth, states left on the queue, the violated
property, the error and the counterexample trace, step by step with its actions."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import CORPUS, ERRORS, REPO, load_expected, run_safestate
from safestate import mutants
from safestate.checker import explore, shard_worker
from safestate.checker.explore import CheckResult, explore_states
from safestate.checker.model import load_model

# The errors corpus's specs whose search starts (the others fail while loading).
SEARCH_ERRORS = ["AssertInInvariant", "CaseNoMatch", "ChooseNoWitness", "DomainError", "HeadOfEmpty",
                 "InvariantErrorInInit", "PrimedUnbound", "TypeMismatch", "Unbounded"]


def _outcome(r: CheckResult) -> tuple:
    trace = [(s.state, s.action, s.params) for s in r.trace or []]
    error = (r.error.kind, r.error.message) if r.error else None
    return (r.result, r.distinct_states, r.states_generated, r.depth, r.left_on_queue, r.violated, error, trace)


def _both(tla: Path, cfg: Path | None = None) -> tuple[tuple, tuple]:
    one = explore_states(load_model(str(tla), None if cfg is None else str(cfg)), workers=1)
    two = explore_states(load_model(str(tla), None if cfg is None else str(cfg)), workers=2)
    return _outcome(one), _outcome(two)


@pytest.mark.parametrize("name", sorted(load_expected(CORPUS)))
def test_two_workers_give_the_single_worker_result_on_corpus_spec(name: str) -> None:
    # Covers SYMMETRY (TwoPhaseSym, SymUnion), VIEW (TrafficView), CONSTRAINT (Constraints,
    # ConstraintEdge), deadlock (VendingMachine), violations at depth (JugPuzzle, NaiveMutex).
    one, two = _both(CORPUS / f"{name}.tla")
    assert two == one


@pytest.mark.parametrize("name", SEARCH_ERRORS)
def test_two_workers_report_the_single_worker_evaluation_error(name: str) -> None:
    one, two = _both(ERRORS / f"{name}.tla")
    assert one[0] == "error"
    assert two == one


WIDE = """---- MODULE Wide ----
EXTENDS Naturals
VARIABLES x, y
Init == x = 0 /\\ y = 0
Next == \\/ x < 30 /\\ x' = x + 1 /\\ y' = y
        \\/ y < 30 /\\ y' = y + 1 /\\ x' = x
        \\/ x > 0 /\\ y > 0 /\\ x' = x - 1 /\\ y' = y - 1
Small == x + y < 25
===="""


def test_two_workers_find_the_single_worker_counterexample_among_many_at_the_same_depth(tla_dir) -> None:
    # 26 states violate Small at depth 26; the single worker reports the first in TLC's
    # generation order, and so must the sharded search (levels of hundreds of states).
    tla = tla_dir("Wide", WIDE, "INIT Init\nNEXT Next\nINVARIANT Small\n")
    one, two = _both(tla)
    assert one[0] == "safety failure" and len(one[7]) == 26
    assert two == one


def test_two_workers_count_a_complete_search_as_one(tla_dir) -> None:
    tla = tla_dir("Wide", WIDE, "INIT Init\nNEXT Next\n")
    one, two = _both(tla)
    assert one[:5] == ("success", 961, 2761, 61, 0)
    assert two == one


def test_two_workers_give_the_single_worker_trace_on_flagship_mutants(tmp_path: Path) -> None:
    flagship = REPO / "models" / "SystemStateManager.tla"
    killed = [m for m in mutants.load(REPO / "models" / "mutants" / "SystemStateManager.toml")
              if m.expect == "violated" and m.trace_length is not None and m.trace_length <= 3]
    assert len(killed) >= 2
    for m in killed[:2]:
        tla = mutants.variant(flagship, m.invariant, tmp_path / m.id, m.patches, m.id)
        one, two = _both(tla)
        assert one[0] == "safety failure" and len(one[7]) == m.trace_length, m.id
        assert two == one, m.id


def test_two_workers_stop_at_the_memory_limit(tla_dir, monkeypatch: pytest.MonkeyPatch) -> None:
    # The workers (forked, so they see this patch) find themselves over their share.
    monkeypatch.setattr(shard_worker, "pss_mb", lambda: 1e9)
    r = explore_states(load_model(str(tla_dir("Wide", WIDE, "INIT Init\nNEXT Next\n"))), workers=2,
                       max_memory_mb=4000)
    assert r.result == "error" and r.error is not None and r.error.kind == "memory"
    assert r.error.message.startswith("memory limit of 4000 MB exceeded after 1 distinct states")


def test_two_workers_print_progress_lines(tla_dir, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(explore, "PROGRESS_SECONDS", 0.0)
    lines: list[str] = []
    explore_states(load_model(str(tla_dir("Wide", WIDE, "INIT Init\nNEXT Next\n"))), workers=2,
                   progress=lines.append)
    assert "Progress(61): 2760 states generated, 961 distinct states found, 1 states left on queue." in lines


def test_a_crashed_worker_makes_the_search_restart_with_one_worker(tla_dir, monkeypatch, capsys) -> None:
    def crash(self, fresh):  # noqa: ANN001
        raise RuntimeError("simulated defect")
    monkeypatch.setattr(shard_worker.ShardWorker, "_merge", crash)
    one, two = _both(tla_dir("Wide", WIDE, "INIT Init\nNEXT Next\nINVARIANT Small\n"))
    assert two == one
    assert "the parallel search failed (RuntimeError: simulated defect); searching again with one worker" \
        in capsys.readouterr().err


def test_json_reports_the_workers_cpu() -> None:
    p = run_safestate("check", str(CORPUS / "AllAssigned.tla"), "--json", "--workers", "2")
    par = json.loads(p.stdout)["parallel"]
    assert par["workers"] == 2 and len(par["worker_cpu_seconds"]) == 2
    assert par["critical_path_cpu_seconds"] >= max(par["worker_cpu_seconds"]) / 2

