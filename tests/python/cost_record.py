"""Records what each test costs, as it ends: with SAFESTATE_TEST_COSTS=FILE set, one JSON
line per test is appended to FILE: the node id, its wall seconds and its CPU seconds (the
worker process, the subprocesses it waited for and the process trees named in
COMPANION_SESSIONS, setup and teardown included).  CPU
seconds are what the scheduler's cost table wants (`scripts/test_costs.py`): on a shared,
loaded machine wall time says more about the neighbours than about the test.  A line is
written per test, so an interrupted run still leaves its measurements."""

from __future__ import annotations

import json
import os
import resource
import time
from collections.abc import Callable, Generator

import pytest

ENV = "SAFESTATE_TEST_COSTS"


# Session ids of process trees a fixture started, each led by a child of this process,
# whose work is done for the tests while this process does not wait for it (a Ray
# cluster's head and the actors it starts): their CPU counts too, or the scheduler would
# take a file whose work runs there for a cheap one.  The fixture ends one with
# `wait_for_companion`.
COMPANION_SESSIONS: set[int] = set()


def children_cpu_seconds() -> float:
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return kids.ru_utime + kids.ru_stime


def cpu_seconds() -> float:
    own = resource.getrusage(resource.RUSAGE_SELF)
    return own.ru_utime + own.ru_stime + children_cpu_seconds() + companion_cpu_seconds()


_companion_seen: dict[int, float] = {}
_reaped: list[float] = [0.0]  # what waiting for the leaders added to RUSAGE_CHILDREN


def wait_for_companion(sid: int, wait: Callable[[], object]) -> None:
    """Wait for the session's leader (`wait()`) and stop reading its tree: its CPU stays
    counted as last read (a leader that exits before reaping its children would take
    theirs with it), not a second time in RUSAGE_CHILDREN."""
    companion_cpu_seconds()
    before = children_cpu_seconds()
    try:
        wait()
    finally:
        _reaped[0] += children_cpu_seconds() - before
        COMPANION_SESSIONS.discard(sid)


def companion_cpu_seconds() -> float:
    """CPU seconds of the processes of COMPANION_SESSIONS and of the children they reaped
    (Linux /proc; 0 elsewhere), as the most read so far per session: it never decreases
    when the tree's processes end."""
    if not COMPANION_SESSIONS or not os.path.isdir("/proc"):
        return sum(_companion_seen.values()) - _reaped[0]
    ticks = dict.fromkeys(COMPANION_SESSIONS, 0)
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat", encoding="ascii", errors="replace") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:  # ended meanwhile
            continue
        if int(fields[3]) in ticks:  # the session; then utime, stime, cutime, cstime
            ticks[int(fields[3])] += sum(int(x) for x in fields[11:15])
    for sid, n in ticks.items():
        _companion_seen[sid] = max(_companion_seen.get(sid, 0.0), n / os.sysconf("SC_CLK_TCK"))
    return sum(_companion_seen.values()) - _reaped[0]


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
