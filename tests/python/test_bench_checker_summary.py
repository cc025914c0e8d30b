"""bench/bench_checker.py's summary (issue 32): per spec, the default engine's rate over
TLC's at 1 worker and its 2-worker over 1-worker throughput by thread CPU; without TLC the
ratios are said to be skipped, never left blank or made up."""

from __future__ import annotations

import importlib.util
import sys
from types import ModuleType

import pytest

from conftest import REPO


@pytest.fixture(scope="module")
def bench() -> ModuleType:
    spec = importlib.util.spec_from_file_location("bench_checker", REPO / "bench" / "bench_checker.py")
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    sys.modules["bench_checker"] = mod  # dataclasses resolve their module by name
    spec.loader.exec_module(mod)
    return mod


def _runs(bench: ModuleType):  # type: ignore[no-untyped-def]
    # 1 worker: 10 CPU s; 2 workers: 1 CPU s outside the search, a 5 s critical path.
    one = bench.Run(1000, 11.0, 10.0, None, "success")
    two = bench.Run(1000, 7.0, 12.0, None, "success", critical_cpu=6.0, outside_cpu=1.0, critical_search_cpu=5.0)
    tlc = bench.Run(1000, 30.0, 40.0, None, "success")
    return one, two, tlc


def test_summary_gives_the_tlc_ratio_and_the_thread_cpu_speedup(bench: ModuleType) -> None:
    one, two, tlc = _runs(bench)
    assert bench.thread_speedup(one, two) == pytest.approx(9.0 / 5.0)
    lines = bench.summary([bench.Row("MCLamportMutex", True, one, two, tlc)], "auto", "/x/tla2tools.jar")
    row = lines[-1].split()
    assert row[:3] == ["MCLamportMutex", "yes", "1000"]
    assert row[5] == "4.00x" and row[6] == "1.80x"


def test_summary_without_tlc_says_the_ratio_is_skipped(bench: ModuleType) -> None:
    one, two, _ = _runs(bench)
    lines = bench.summary([bench.Row("Counters", False, one, two, None)], "auto", None)
    assert lines[-2].split()[4:6] == ["skipped", "skipped"]
    assert lines[-1].startswith("TLC: skipped (TLA2TOOLS_JAR is not set")


def test_speedup_is_not_claimed_when_the_runs_disagree_or_the_spec_is_too_small(bench: ModuleType) -> None:
    one, two, _ = _runs(bench)
    assert bench.thread_speedup(bench.Run(999, 11.0, 10.0, None, "success"), two) is None
    assert bench.thread_speedup(bench.Run(1000, 1.0, 0.5, None, "success"), two) is None
