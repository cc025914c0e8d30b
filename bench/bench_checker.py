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

At the end, one summary row per spec (issue 32's two ratios, measured in this run): the
default engine's distinct states per CPU second over TLC's, 1 worker (target >= 2x), and
its 2-worker throughput over its 1-worker throughput by thread CPU (target >= 1.8x): the
1-worker run's search CPU over the 2-worker run's critical path (the slowest worker's CPU
per level summed, plus the coordinator's), both without the process's CPU outside the
search (start, loading, translation: the 2-worker run's CPU outside its threads' search,
the same work in both runs).  Without TLA2TOOLS_JAR the TLC ratios are skipped, said in
one line.

Default specs: bench/specs/*.tla and the flagship model with its CI .cfg.

With `--engines auto,python` each of our runs is made with each engine (`safestate
check --engine E`); the default, `auto`, is what `safestate check` runs by default.

`--examples DIR` (a checkout of github.com/tlaplus/Examples, not part of this
repository; default $TLAPLUS_EXAMPLES) adds the published specs of `PUBLISHED` to the run,
each with the .cfg the Examples repository checks it with; `--published-only` runs only
those.

usage: bench/bench_checker.py [--workers 1,2] [--engines auto] [--quick] [--examples DIR] [--published-only]
                              [SPEC.tla[:CFG] ...]
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
    # Ours with several workers: the process's CPU outside the search (start, loading,
    # translation, report), and the search's critical path alone.
    outside_cpu: float | None = None
    critical_search_cpu: float | None = None

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
    critical = outside = None
    if parallel:
        # The run's CPU outside the search (start, loading, translation, report) is on the
        # critical path too, so the ratio compares like with like against one.cpu.
        search = sum(parallel["worker_cpu_seconds"]) + parallel["coordinator_cpu_seconds"]
        outside = cpu - search
        critical = outside + parallel["critical_path_cpu_seconds"]
    return Run(summary.get("distinct_states"), wall, cpu, usage.ru_maxrss, summary.get("result", "error"), critical,
               outside, parallel["critical_path_cpu_seconds"] if parallel else None)


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
    if args.published_only:
        if not extra:
            raise SystemExit("bench_checker: --published-only needs a tlaplus/Examples checkout "
                             "(--examples DIR or $TLAPLUS_EXAMPLES)")
        return extra
    if args.specs:
        out = []
        for s in args.specs:
            tla, _, cfg = s.partition(":")
            out.append((Path(tla), Path(cfg) if cfg else Path(tla).with_suffix(".cfg")))
        return extra + out
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
    return extra + out + [FLAGSHIP]  # the published specs first


def fmt_run(who: str, name: str, workers: int, r: Run, engine: str = "-") -> str:
    per_state = f"{r.peak_kib * 1024 / r.distinct:>8.0f}" if r.peak_kib and r.distinct else f"{'-':>8}"
    line = (f"{name:18} {who:5} {engine:7} {workers:>2} {r.distinct if r.distinct is not None else '-':>10} "
            f"{r.wall:>8.2f} {r.cpu:>8.2f} {r.rate:>10.0f} {per_state}")
    return line


@dataclass
class Row:
    """A spec's summary: the default engine's figures and TLC's, 1 and 2 workers."""
    spec: str
    published: bool
    ours1: Run | None = None
    ours2: Run | None = None
    tlc1: Run | None = None


def thread_speedup(one: Run, two: Run) -> float | None:
    """2 workers' throughput over 1 worker's by thread CPU: the 1-worker run's search CPU
    (its CPU less the CPU outside the search, which the 2-worker run measured) over the
    2-worker run's critical path of the search."""
    if two.outside_cpu is None or not two.critical_search_cpu or not one.distinct or one.distinct != two.distinct:
        return None
    search1 = one.cpu - two.outside_cpu
    return search1 / two.critical_search_cpu if search1 > 0 else None  # a spec too small to tell


def summary(rows: list[Row], engine: str, jar: str | None) -> list[str]:
    out = [f"summary: the {engine} engine (safestate check's default: auto); ours/TLC: distinct states per CPU s, "
           "1 worker, target >= 2x; 2w/1w: throughput by thread CPU, target >= 1.8x",
           f"{'spec':18} {'published':9} {'distinct':>10} {'ours 1w':>10} {'TLC 1w':>10} {'ours/TLC':>9} "
           f"{'2w/1w':>7}"]
    for r in rows:
        d = r.ours1.distinct if r.ours1 and r.ours1.distinct is not None else "-"
        ours = f"{r.ours1.rate:>10.0f}" if r.ours1 else f"{'-':>10}"
        if not jar:
            tlc, ratio = f"{'skipped':>10}", f"{'skipped':>9}"
        elif r.tlc1 is None or not r.tlc1.rate:
            tlc, ratio = f"{'-':>10}", f"{'-':>9}"
        else:
            tlc = f"{r.tlc1.rate:>10.0f}"
            ratio = f"{r.ours1.rate / r.tlc1.rate:>8.2f}x" if r.ours1 else f"{'-':>9}"
            if r.ours1 and r.tlc1.distinct != r.ours1.distinct:
                ratio += f"  DISTINCT DIFFERS (TLC {r.tlc1.distinct})"
        sp = thread_speedup(r.ours1, r.ours2) if r.ours1 and r.ours2 else None
        speed = f"{sp:>6.2f}x" if sp is not None else f"{'-':>7}"
        out.append(f"{r.spec:18} {'yes' if r.published else 'no':9} {d:>10} {ours} {tlc} {ratio} {speed}")
    if not jar:
        out.append("TLC: skipped (TLA2TOOLS_JAR is not set; set it to TLC 1.8.0's tla2tools.jar for the ratios)")
    return out


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--workers", default="1,2", help="comma-separated worker counts (default 1,2)")
    ap.add_argument("--engines", default="auto", help="our engines to run, comma-separated: auto (the default "
                    "engine of safestate check), native, python (default auto)")
    ap.add_argument("--examples", metavar="DIR", default=os.environ.get("TLAPLUS_EXAMPLES") or None,
                    help="a tlaplus/Examples checkout (default $TLAPLUS_EXAMPLES): also run its published specs "
                    "(" + ", ".join(Path(t).stem for t, _ in PUBLISHED) + ")")
    ap.add_argument("--tlc-workers", help="TLC's worker counts, comma-separated (default: those of --workers)")
    ap.add_argument("--published-only", action="store_true", help="run only the published specs of --examples")
    ap.add_argument("--quick", action="store_true", help="shrink the bench specs' constants 4x")
    ap.add_argument("specs", nargs="*", help="SPEC.tla or SPEC.tla:CFG (default: bench/specs/*.tla, flagship)")
    args = ap.parse_args()
    counts = [int(w) for w in args.workers.split(",")]
    tlc_counts = [int(w) for w in args.tlc_workers.split(",")] if args.tlc_workers else counts
    engines = args.engines.split(",")
    jar = tlc_jar()
    if not jar:
        print("TLC: skipped (TLA2TOOLS_JAR is not set): no ours/TLC ratios in this run", flush=True)
    if not args.examples:
        print("published specs: skipped (no tlaplus/Examples checkout: --examples DIR or $TLAPLUS_EXAMPLES)", flush=True)
    published_paths = {tla for tla, _ in published(Path(args.examples))} if args.examples else set()
    rows: list[Row] = []
    print(f"{'spec':18} {'who':5} {'engine':7} {'w':>2} {'distinct':>10} {'wall s':>8} {'CPU s':>8} {'dist/CPUs':>10} "
          f"{'B/state':>8}  ratios")
    for tla, cfg in spec_list(args):
        ours1: dict[str, Run] = {}
        tlc1: Run | None = None
        row = Row(tla.stem, tla in published_paths)
        rows.append(row)
        for w in counts:
            t = run_theirs(jar, tla, cfg, w) if jar and w in tlc_counts else None
            for engine in engines:
                r = run_ours(tla, cfg, w, engine)
                ratios = []
                if t is not None and t.rate:
                    ratios.append(f"ours/TLC {r.rate / t.rate:.2f}x")
                    if t.distinct != r.distinct:
                        ratios.append(f"DISTINCT DIFFERS (TLC {t.distinct})")
                if engine == engines[0]:
                    if w == 1:
                        row.ours1 = r
                    elif w == 2:
                        row.ours2 = r
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
                if w == 1:
                    row.tlc1 = t
                extra = ""
                if w == counts[0]:
                    tlc1 = t
                elif tlc1 is not None and t.wall:
                    extra = f"  TLC {w}w/{counts[0]}w wall speed-up {tlc1.wall / t.wall:.2f}x"
                print(fmt_run("TLC", tla.stem, w, t) + extra, flush=True)
    print()
    for line in summary(rows, engines[0], jar):
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
