"""Records what each test costs, as it ends: with SAFESTATE_TEST_COSTS=FILE set, one JSON
line per test is appended to FILE: the node id, its wall seconds and its CPU seconds (the
worker process and the subprocesses it waited for, setup and teardown included).  CPU
seconds are what the scheduler's cost table wants (`scripts/test_costs.py`): on a shared,
loaded machine wall time says more about the neighbours than about the test.  A line is
written per test, so an interrupted run still leaves its measurements."""

from __future__ import annotations

import json
import os
import resource
import time
from collections.abc import Generator

import pytest

ENV = "SAFESTATE_TEST_COSTS"


def cpu_seconds() -> float:
    own = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item) -> Generator[None, None, None]:
    path = os.environ.get(ENV)
    if not path:
        yield
        return
    wall, cpu = time.monotonic(), cpu_seconds()
    yield
    line = json.dumps({"test": item.nodeid, "wall": round(time.monotonic() - wall, 3),
                       "cpu": round(cpu_seconds() - cpu, 3)})
    with open(path, "a", encoding="utf-8") as f:
        f.write(line + "\n")
