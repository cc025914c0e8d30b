#!/usr/bin/env python3
"""Benchmark of `safestate check` against TLC: distinct states per CPU second.

For each spec, runs `safestate check --json` (a fresh process) with each worker
count in `--workers` (default 1,2) and, when TLA2TOOLS_JAR names a jar, TLC with
the same worker counts, in the same run.  CPU seconds are the child process's
user+system time, its worker processes included (os.wait4 / RUSAGE_CHILDREN), so
the figures hold on a busy machine where wall time does not.  Printed per run:
distinct states, wall and CPU seconds, distinct states per CPU second, peak RSS
per distinct state, and the ratios: ours/TLC at the same worker count, and each
run's rate over its own single-worker rate (the parallel speed-up, by wall time, and
the load-independent one: the single worker's CPU over the parallel run's critical
path, the slowest worker's CPU per BFS phase summed, as `--json` reports it, plus the
run's CPU outside the search: start, loading, translation).
Informational only: never pass/fail.

Default specs: bench/specs/*.tla and the flagship model with its CI .cfg.

With `--engines auto,python` each of our runs is made with each engine (`safestate
check --engine E`); the default, `auto`, is what `safestate check` runs by default.

`--examples DIR` (a checkout of github.com/tlaplus/Examples, not part of this
repository) adds the published specs of `PUBLISHED` to the run, each with the .cfg
the Examples repository checks it with.

usage: bench/bench_checker.py [--workers 1,2] [--engines auto] [--quick] [--examples DIR] [SPEC.tla[:CFG] ...]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "python"))

from safestate.checker.tlc import run_tlc, tlc_jar  # noqa: E402

FLAGSHIP = (REPO / "models" / "SystemStateManager.tla", REPO / "models" / "SystemStateManager.cfg")
# Published specs (paths in tlaplus/Examples) large enough for a rate: the module and its cfg.
PUBLISHED = [
    ("specifications/lamport_mutex/MCLamportMutex.tla", "specifications/lamport_mutex/MCLamportMutex.cfg"),
]


@dataclass
class Run:
    distinct: int | None
    wall: float
    cpu: float
    peak_kib: int | None  # None for TLC: the JVM's heap is not the state store's size
    result: str
    # Ours with several workers: CPU s of the slowest worker per BFS phase, summed, plus
    # the coordinator's and the process's outside the search (the wall time the run
    # would take on idle cores).
    critical_cpu: float | None = None

    @property
    def rate(self) -> float:
        """Distinct states per CPU second."""
        return (self.distinct or 0) / self.cpu if self.cpu else 0.0


def run_ours(tla: Path, cfg: Path, workers: int, engine: str = "python") -> Run:
    cmd = [sys.executable, "-c", "import sys; from safestate.cli import main; sys.exit(main())",
           "check", str(tla), "--config", str(cfg), "--workers", str(workers), "--engine", engine, "--json"]
    env = dict(os.environ, PYTHONPATH=str(REPO / "python"), PYTHONHASHSEED="0")
    start = time.monotonic()
    with tempfile.TemporaryFile() as out:
        p = subprocess.Popen(cmd, stdout=out, stderr=subprocess.DEVNULL, env=env)
        _, _, usage = os.wait4(p.pid, 0)
        p.returncode = 0  # reaped by wait4
        wall = time.monotonic() - start
        out.seek(0)
        text = out.read().decode()
    try:
        summary = json.loads(text)
    except json.JSONDecodeError:
        return Run(None, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss, "no JSON output")
    cpu = usage.ru_utime + usage.ru_stime
    parallel = summary.get("parallel")
    critical = None
    if parallel:
        # The run's CPU outside the search (start, loading, translation, report) is on the
        # critical path too, so the ratio compares like with like against one.cpu.
        search = sum(parallel["worker_cpu_seconds"]) + parallel["coordinator_cpu_seconds"]
        critical = cpu - search + parallel["critical_path_cpu_seconds"]
    return Run(summary.get("distinct_states"), wall, cpu, usage.ru_maxrss, summary.get("result", "error"), critical)


def run_theirs(jar: str, tla: Path, cfg: Path, workers: int) -> Run:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    s = run_tlc(jar, str(tla), str(cfg), workers=workers)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return Run(s.distinct_states, wall, cpu, None, s.result)


def published(examples: Path) -> list[tuple[Path, Path]]:
    out = []
    for tla, cfg in PUBLISHED:
        if not (examples / tla).exists():
            raise SystemExit(f"bench_checker: {examples / tla} not found (is {examples} a tlaplus/Examples checkout?)")
        out.append((examples / tla, examples / cfg))
    return out


def spec_list(args: argparse.Namespace) -> list[tuple[Path, Path]]:
    extra = published(Path(args.examples)) if args.examples else []
    if args.specs or extra:
        out = []
        for s in args.specs:
            tla, _, cfg = s.partition(":")
            out.append((Path(tla), Path(cfg) if cfg else Path(tla).with_suffix(".cfg")))
        return out + extra
    out = [(tla, tla.with_suffix(".cfg")) for tla in sorted((REPO / "bench" / "specs").glob("*.tla"))]
    if args.quick:
        # Each constant 4x smaller (at least 2): a smoke run of the bench itself.
        tmp = Path(tempfile.mkdtemp())
        quick = []
        for tla, cfg in out:
            small = tmp / cfg.name
            small.write_text(re.sub(r"= (\d+)", lambda m: f"= {max(2, int(m.group(1)) // 4)}", cfg.read_text()))
            quick.append((tla, small))
        out = quick
    return out + [FLAGSHIP]


def fmt_run(who: str, name: str, workers: int, r: Run, engine: str = "-") -> str:
    per_state = f"{r.peak_kib * 1024 / r.distinct:>8.0f}" if r.peak_kib and r.distinct else f"{'-':>8}"
    line = (f"{name:18} {who:5} {engine:7} {workers:>2} {r.distinct if r.distinct is not None else '-':>10} "
            f"{r.wall:>8.2f} {r.cpu:>8.2f} {r.rate:>10.0f} {per_state}")
    return line


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--workers", default="1,2", help="comma-separated worker counts (default 1,2)")
    ap.add_argument("--engines", default="auto", help="our engines to run, comma-separated: auto (the default "
                    "engine of safestate check), native, python (default auto)")
    ap.add_argument("--examples", metavar="DIR", help="a tlaplus/Examples checkout: also run its published specs "
                    "(" + ", ".join(Path(t).stem for t, _ in PUBLISHED) + ")")
    ap.add_argument("--quick", action="store_true", help="shrink the bench specs' constants 4x")
    ap.add_argument("specs", nargs="*", help="SPEC.tla or SPEC.tla:CFG (default: bench/specs/*.tla, flagship)")
    args = ap.parse_args()
    counts = [int(w) for w in args.workers.split(",")]
    engines = args.engines.split(",")
    jar = tlc_jar()
    print(f"{'spec':18} {'who':5} {'engine':7} {'w':>2} {'distinct':>10} {'wall s':>8} {'CPU s':>8} {'dist/CPUs':>10} "
          f"{'B/state':>8}  ratios")
    for tla, cfg in spec_list(args):
        ours1: dict[str, Run] = {}
        tlc1: Run | None = None
        for w in counts:
            t = run_theirs(jar, tla, cfg, w) if jar else None
            for engine in engines:
                r = run_ours(tla, cfg, w, engine)
                ratios = []
                if t is not None and t.rate:
                    ratios.append(f"ours/TLC {r.rate / t.rate:.2f}x")
                    if t.distinct != r.distinct:
                        ratios.append(f"DISTINCT DIFFERS (TLC {t.distinct})")
                if w == counts[0]:
                    ours1[engine] = r
                elif engine in ours1 and r.wall:
                    one = ours1[engine]
                    ratios.append(f"ours {w}w/{counts[0]}w wall speed-up {one.wall / r.wall:.2f}x")
                    if r.critical_cpu:
                        # Load-independent: the single worker's CPU over this run's critical path.
                        ratios.append(f"critical path {r.critical_cpu:.2f} CPU s, speed-up on idle cores "
                                      f"{one.cpu / r.critical_cpu:.2f}x")
                note = "" if r.result == "success" else f"  ({r.result})"
                print(fmt_run("ours", tla.stem, w, r, engine) + "  " + ", ".join(ratios) + note, flush=True)
            if t is not None:
                extra = ""
                if w == counts[0]:
                    tlc1 = t
                elif tlc1 is not None and t.wall:
                    extra = f"  TLC {w}w/{counts[0]}w wall speed-up {tlc1.wall / t.wall:.2f}x"
                print(fmt_run("TLC", tla.stem, w, t) + extra, flush=True)
    if not jar:
        print("(set TLA2TOOLS_JAR to compare with TLC)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
