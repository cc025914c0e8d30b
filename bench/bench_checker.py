#!/usr/bin/env python3
"""Benchmark of `safestate check`: distinct states per second.

Runs (a) the synthetic bench/specs/Counters spec (1,680,000 distinct states), and
(b) every model under models/ that has a .cfg beside it.  When TLA2TOOLS_JAR names
a jar, TLC runs on the same specs with the same number of workers and the ratio
of distinct states per second (ours/TLC, wall clock) is printed.  "ours cpu" is
the CPU time of our process (parent only), less sensitive to a busy machine.
Informational only: never pass/fail.

usage: bench/bench_checker.py [--workers N] [--quick] [SPEC.tla ...]
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "python"))

from safestate.checker.explore import explore_states  # noqa: E402
from safestate.checker.model import load_model  # noqa: E402
from safestate.checker.tlc import run_tlc, tlc_jar  # noqa: E402


def bench_ours(tla: Path, cfg: Path, workers: int) -> tuple[float, float, int, str]:
    start, cpu = time.monotonic(), time.process_time()
    model = load_model(str(tla), str(cfg))
    r = explore_states(model, workers=workers)
    return time.monotonic() - start, time.process_time() - cpu, r.distinct_states, r.result


def bench_tlc(jar: str, tla: Path, cfg: Path, workers: int) -> tuple[float, int | None]:
    start = time.monotonic()
    s = run_tlc(jar, str(tla), str(cfg), workers=workers)
    return time.monotonic() - start, s.distinct_states


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--quick", action="store_true", help="shrink the synthetic spec's bounds 4x")
    ap.add_argument("specs", nargs="*")
    args = ap.parse_args()
    specs: list[tuple[Path, Path]] = []
    if args.specs:
        specs = [(Path(s), Path(s).with_suffix(".cfg")) for s in args.specs]
    else:
        synth = REPO / "bench" / "specs" / "Counters.tla"
        cfg = synth.with_suffix(".cfg")
        if args.quick:
            quick = Path(tempfile.mkdtemp()) / "Counters.cfg"
            quick.write_text(re.sub(r"= (\d+)", lambda m: f"= {max(2, int(m.group(1)) // 4)}", cfg.read_text()))
            cfg = quick
        specs.append((synth, cfg))
        for tla in sorted((REPO / "models").rglob("*.tla")):
            if tla.with_suffix(".cfg").exists():
                specs.append((tla, tla.with_suffix(".cfg")))
    jar = tlc_jar()
    print(f"workers: {args.workers}")
    print(f"{'spec':24} {'distinct':>10} {'ours s':>8} {'ours cpu':>8} {'ours st/s':>10} {'TLC s':>8} "
          f"{'TLC st/s':>10} {'ratio':>6}")
    for tla, cfg in specs:
        try:
            secs, cpu, distinct, result = bench_ours(tla, cfg, args.workers)
        except Exception as e:  # noqa: BLE001 - a benchmark reports and goes on
            print(f"{tla.name:24} error: {e}")
            continue
        rate = distinct / secs if secs else 0.0
        line = f"{tla.stem:24} {distinct:>10} {secs:>8.2f} {cpu:>8.2f} {rate:>10.0f}"
        if jar:
            tsecs, tdistinct = bench_tlc(jar, tla, cfg, args.workers)
            trate = (tdistinct or 0) / tsecs if tsecs else 0.0
            line += f" {tsecs:>8.2f} {trate:>10.0f} {rate / trate if trate else 0:>6.2f}"
        print(line + ("" if result == "success" else f"  ({result})"), flush=True)
    if not jar:
        print("(set TLA2TOOLS_JAR to compare with TLC)")
    return 0


if __name__ == "__main__":
    os.environ.setdefault("PYTHONHASHSEED", "0")
    sys.exit(main())
