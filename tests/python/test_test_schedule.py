"""The test command's worker schedule (docs/testing.md, tests/python/cost_schedule.py):
a file is one unit of work except the independent tests named in SPREAD, and a worker is
always handed the unit with the largest measured cost; the cost recording of
SAFESTATE_TEST_COSTS is read back by scripts/test_costs.py."""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from collections import OrderedDict
from pathlib import Path

import pytest

import cost_record
from conftest import REPO

pytest.importorskip("xdist")
from cost_schedule import SPREAD, CostOrderedFileScheduling, load_costs  # noqa: E402

MUTANT = SPREAD[0] + "SystemStateManager:release_to_idle]"


class FakeWorker:
    """A worker as the scheduler sees it: it is sent the indexes of the tests to run."""

    def __init__(self) -> None:
        self.sent: list[list[int]] = []

    def send_runtest_some(self, indexes: list[int]) -> None:
        self.sent.append(indexes)


def scheduler(costs: dict[str, float], collection: list[str]) -> tuple[CostOrderedFileScheduling, FakeWorker]:
    sched = CostOrderedFileScheduling.__new__(CostOrderedFileScheduling)  # no xdist session behind it
    sched.costs = costs
    worker = FakeWorker()
    sched.registered_collections = {worker: collection}  # type: ignore[dict-item]
    sched.assigned_work = {}
    sched.workqueue = OrderedDict()
    for nodeid in collection:
        sched.workqueue.setdefault(sched._split_scope(nodeid), {})[nodeid] = False
    return sched, worker


def test_spread_tests_are_units_of_their_own_and_other_tests_share_their_file() -> None:
    sched, _ = scheduler({}, [])
    assert sched._split_scope(MUTANT) == MUTANT
    assert sched._split_scope("tests/python/test_checker_cfg.py::test_a[x]") == "tests/python/test_checker_cfg.py"
    witness = "tests/python/test_model_mutants.py::test_witness_is_reached[SystemStateManager:Witness_X]"
    assert sched._split_scope(witness) == "tests/python/test_model_mutants.py"  # shares a module fixture


def test_the_costliest_unit_is_handed_out_first_whatever_its_number_of_tests() -> None:
    many = [f"tests/python/test_many.py::test_{i}" for i in range(20)]
    few = ["tests/python/test_few.py::test_a", "tests/python/test_few.py::test_b"]
    collection = many + few + [MUTANT]
    costs = {few[0]: 100.0, few[1]: 50.0, MUTANT: 30.0}  # the 20 unlisted tests: 0.5 s each
    sched, worker = scheduler(costs, collection)
    order = []
    while sched.workqueue:
        sched._assign_work_unit(worker)  # type: ignore[arg-type]
        order.append(sorted(collection[i].split("::")[0] for i in worker.sent[-1]))
    assert order == [["tests/python/test_few.py"] * 2, ["tests/python/test_model_mutants.py"],
                     ["tests/python/test_many.py"] * 20]


def test_cost_records_are_read_back_and_written_as_the_cost_table(tmp_path: Path, monkeypatch) -> None:
    spec = importlib.util.spec_from_file_location("test_costs_script", REPO / "scripts" / "test_costs.py")
    assert spec is not None and spec.loader is not None
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    log = tmp_path / "costs.jsonl"
    log.write_text(json.dumps({"test": "tests/python/test_a.py::test_x", "wall": 3.0, "cpu": 1.25}) + "\n"
                   + json.dumps({"test": MUTANT, "wall": 9.0, "cpu": 4.5}) + "\n")
    monkeypatch.setattr(script, "OUT", tmp_path / "test_costs.json")
    assert script.main([str(log), "--write"]) == 0
    assert load_costs(tmp_path / "test_costs.json") == {"tests/python/test_a.py::test_x": 1.25, MUTANT: 4.5}
    log.write_text("not json\n")
    with pytest.raises(SystemExit, match="costs.jsonl:1: not a cost record"):
        script.main([str(log)])


BURN = "import time\nwhile time.process_time() < 0.3:\n    pass\nprint('burnt', flush=True)\ntime.sleep(120)\n"


@pytest.mark.skipif(not os.path.isdir("/proc"), reason="reads /proc")
def test_a_companion_process_trees_cpu_counts_once_and_never_drops_when_it_ends() -> None:
    # A process this one does not wait for while the tests run (a Ray cluster's head):
    # its CPU (0.3 s, read in clock ticks) is the tests' cost; once it is waited for, it
    # is in RUSAGE_CHILDREN too, and must not count twice.
    child = subprocess.Popen([sys.executable, "-c", BURN], stdout=subprocess.PIPE, text=True, start_new_session=True)
    try:
        assert child.stdout is not None and child.stdout.readline() == "burnt\n"
        alone = cost_record.cpu_seconds()
        cost_record.COMPANION_SESSIONS.add(child.pid)
        with_child = cost_record.cpu_seconds()
        assert with_child >= alone + 0.25
        child.kill()
        cost_record.wait_for_companion(child.pid, child.wait)
        reaped = cost_record.cpu_seconds()
        assert with_child <= reaped < with_child + 0.25
    finally:
        child.kill()
        child.wait()
        cost_record.COMPANION_SESSIONS.discard(child.pid)
