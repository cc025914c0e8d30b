"""The pytest-xdist schedule of the test command (`-n 2 --dist loadfile`, docs/testing.md):
longest work first, so the two workers finish together.

xdist's `loadfile` keeps every test of a file on one worker (module and session fixtures
are built once) but hands the files out by their number of tests, so a long file with few
tests (the model mutants: one model check each) started last and ran alone at the end.
This scheduler keeps the file as the unit, except for the tests named in SPREAD
(independent tests without a shared module fixture: each is a unit of its own: the model
mutants, their BMC runs and the models' full checks), and always
hands a worker the unit with the largest measured cost (`test_costs.json`, CPU seconds
per test, written by `scripts/test_costs.py --write` from a run with
SAFESTATE_TEST_COSTS set; a test not listed costs DEFAULT_SECONDS).  The order changes nothing a test sees: only which
worker runs it and when.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from xdist.scheduler import LoadFileScheduling
from xdist.workermanage import WorkerController

COSTS = Path(__file__).with_name("test_costs.json")
DEFAULT_SECONDS = 0.5

# Test functions whose parametrized cases are independent (own tmp_path, no module fixture):
# each case may run on either worker.
SPREAD = (
    "tests/python/test_model_mutants.py::test_mutant_is_killed_by_check_alone[",  # a model check each
    "tests/python/test_prove_mutants.py::test_bmc_agrees_with_tlc[",  # a BMC run each
    "tests/python/test_models.py::test_model_passes_every_invariant_with_tlc_counts[",  # a whole model each
)


def load_costs(path: Path = COSTS) -> dict[str, float]:
    """Seconds per test node id (missing file: every test costs the default)."""
    try:
        return {k: float(v) for k, v in json.loads(path.read_text(encoding="utf-8")).items()}
    except (OSError, ValueError):
        return {}


def is_spread(nodeid: str) -> bool:
    return nodeid.startswith(SPREAD)


class CostOrderedFileScheduling(LoadFileScheduling):
    """`--dist loadfile` with the SPREAD tests as units of their own, longest unit first."""

    def __init__(self, config: pytest.Config, log=None) -> None:  # type: ignore[no-untyped-def]
        super().__init__(config, log)
        self.costs = load_costs()

    def _split_scope(self, nodeid: str) -> str:
        return nodeid if is_spread(nodeid) else super()._split_scope(nodeid)

    def _cost(self, unit: dict[str, bool]) -> float:
        return sum(self.costs.get(nodeid, DEFAULT_SECONDS) for nodeid in unit)

    def _assign_work_unit(self, node: WorkerController) -> None:
        scope = max(self.workqueue, key=lambda s: self._cost(self.workqueue[s]))
        self.workqueue.move_to_end(scope, last=False)
        super()._assign_work_unit(node)
