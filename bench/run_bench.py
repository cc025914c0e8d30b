#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Instruction-count benchmark of one SystemStateManager scan cycle (RSM-15).

Runs bench/bench_cycle (a seeded, realistic random scenario of --cycles scan cycles) for
two implementations of docs/design/system-state-manager.md:

  ssm     safestate::SystemStateManager, the product (transition table + std::variant)
  switch  safestate_bench::SwitchCaseSsm, a flat switch-case baseline (bench/ only)

and reports, per implementation, instructions (callgrind "Ir") per cycle: mean and worst
case, the ratio to the switch-case baseline, and the heap allocations after construction.

Method
  * Only the implementation's cycle() member function is counted: callgrind runs with
    --collect-atstart=no --toggle-collect=<Impl>::cycle(...), so the scenario generator,
    the plant model, submit() and the driver loop cost nothing. Everything cycle() calls
    (kinematics, libm sin/cos, the PLCopen step) is included.
  * Mean: one callgrind run over the whole scenario; total Ir / cycles.
  * Worst case (and percentiles): a second callgrind run of the same scenario in which
    bench_cycle issues CALLGRIND_DUMP_STATS_AT("cycle=<k>") after every cycle, so each
    dump file holds exactly one cycle's Ir. The script reads every dump (and deletes it),
    giving the exact per-cycle distribution; the worst case is the maximum over all the
    cycles of the scenario (not an estimate). The sum of the per-cycle counts is checked
    against the total of the first run.
  * Heap: bench_cycle replaces the global operator new/delete by counting versions and
    prints the allocations during construction and after it (whole scenario, including
    re-initialisations after lockouts); run natively.
  * Cross-check: before measuring, `bench_cycle crosscheck` runs both implementations in
    lockstep on the same scenario and compares the whole status record and the outputs
    after every submit and every cycle; the first divergence is reported.

Usage
  python3 bench/run_bench.py [--build-dir DIR] [--binary PATH] [--cycles N] [--seed S]
                             [--no-worst] [--jobs J]

Needs cmake, a C++17 compiler, Eigen 3 and valgrind. Python standard library only.
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent

IMPLS = {
    # name: (label, callgrind function to count)
    "switch": ("switch-case baseline", "safestate_bench::SwitchCaseSsm::cycle(*"),
    "ssm": ("SystemStateManager (table + variant)", "safestate::SystemStateManager::cycle(*"),
}

TOTALS_RE = re.compile(rb"^(?:totals|summary):\s+(\d+)", re.MULTILINE)
LABEL_RE = re.compile(rb"cycle=(\d+)")


def log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def build(build_dir: Path) -> Path:
    log(f"== building bench_cycle (Release) in {build_dir}")
    subprocess.run(
        ["cmake", "-S", str(REPO), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
         "-DSAFESTATE_BUILD_BENCH=ON", "-DSAFESTATE_BUILD_TESTS=OFF",
         "-DSAFESTATE_BUILD_PYTHON=OFF"],
        check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", str(build_dir), "--target", "bench_cycle"], check=True,
                   stdout=subprocess.DEVNULL)
    return build_dir / "bench" / "bench_cycle"


def run_native(binary: Path, args: list[str]) -> str:
    out = subprocess.run([str(binary), *args], check=False, capture_output=True, text=True)
    if out.returncode not in (0, 1):
        raise SystemExit(f"{binary} {' '.join(args)} failed ({out.returncode}):\n{out.stderr}")
    return out.stdout


def parse_kv(text: str) -> dict[str, str]:
    kv: dict[str, str] = {}
    for line in text.splitlines():
        for tok in line.split():
            if "=" in tok:
                k, _, v = tok.partition("=")
                kv.setdefault(k, v)
    return kv


def callgrind_total(binary: Path, impl: str, cycles: int, seed: int, workdir: Path) -> int:
    """Total Ir of <impl>::cycle over the whole scenario (toggle-collect, one dump)."""
    out_file = workdir / f"callgrind.total.{impl}"
    cmd = ["valgrind", "--tool=callgrind", "--collect-atstart=no",
           f"--toggle-collect={IMPLS[impl][1]}", f"--callgrind-out-file={out_file}",
           str(binary), impl, "--cycles", str(cycles), "--seed", str(seed), "--quiet"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    m = TOTALS_RE.search(out_file.read_bytes())
    if not m:
        raise SystemExit(f"no totals in {out_file}")
    out_file.unlink()
    return int(m.group(1))


def callgrind_per_cycle(binary: Path, impl: str, cycles: int, seed: int,
                        workdir: Path) -> list[int]:
    """Exact Ir of every single cycle: one callgrind dump per cycle."""
    dump_dir = workdir / f"dumps.{impl}"
    dump_dir.mkdir()
    base = dump_dir / "cg"
    cmd = ["valgrind", "--tool=callgrind", "--collect-atstart=no",
           f"--toggle-collect={IMPLS[impl][1]}", f"--callgrind-out-file={base}",
           "--dump-line=no", "--dump-instr=no", "--compress-strings=yes",
           str(binary), impl, "--cycles", str(cycles), "--seed", str(seed), "--per-cycle",
           "--quiet"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    per_cycle = [-1] * cycles

    def drain(final: bool) -> None:
        # Dumps are numbered cg.1, cg.2, ...; while valgrind runs, the highest-numbered file
        # may still be being written, so it is left for the next pass.
        names = [n for n in os.listdir(dump_dir) if n.startswith("cg.")]
        nums = sorted(int(n[3:]) for n in names if n[3:].isdigit())
        if not final and nums:
            nums = nums[:-1]
        for n in nums:
            path = dump_dir / f"cg.{n}"
            data = path.read_bytes()
            lab = LABEL_RE.search(data)
            tot = TOTALS_RE.search(data)
            if lab and tot:
                k = int(lab.group(1))
                if 0 <= k < cycles:
                    per_cycle[k] = int(tot.group(1))
            path.unlink()

    while proc.poll() is None:
        drain(final=False)
        time.sleep(0.5)
    drain(final=True)
    if proc.returncode != 0:
        raise SystemExit(f"callgrind per-cycle run of {impl} failed ({proc.returncode})")
    # The final dump at program exit (no label) holds nothing of cycle(); ignore it.
    missing = sum(1 for v in per_cycle if v < 0)
    if missing:
        raise SystemExit(f"{impl}: {missing} cycles without a dump")
    shutil.rmtree(dump_dir, ignore_errors=True)
    return per_cycle


def percentile(sorted_vals: list[int], p: float) -> int:
    if not sorted_vals:
        return 0
    idx = min(len(sorted_vals) - 1, max(0, int(round(p / 100.0 * (len(sorted_vals) - 1)))))
    return sorted_vals[idx]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build-dir", type=Path, default=REPO / "build" / "bench-release")
    ap.add_argument("--binary", type=Path, help="use this bench_cycle instead of building")
    ap.add_argument("--cycles", type=int, default=200_000)
    ap.add_argument("--seed", type=int, default=20240611)
    ap.add_argument("--no-worst", action="store_true",
                    help="skip the per-cycle run (mean only; worst case not measured)")
    ap.add_argument("--jobs", type=int, default=max(1, min(4, os.cpu_count() or 1)))
    args = ap.parse_args()

    if shutil.which("valgrind") is None:
        raise SystemExit("valgrind not found")
    binary = args.binary if args.binary else build(args.build_dir)
    binary = binary.resolve()

    # 1. Lockstep cross-check.
    log("== cross-check (lockstep, native)")
    cc = run_native(binary, ["crosscheck", "--cycles", str(args.cycles), "--seed", str(args.seed)])

    # 2. Heap allocations and scenario summary (native).
    native = {impl: run_native(binary, [impl, "--cycles", str(args.cycles), "--seed",
                                        str(args.seed)]) for impl in IMPLS}

    # 3. Callgrind runs (in parallel: they are independent processes).
    with tempfile.TemporaryDirectory(prefix="safestate-bench-") as tmp:
        workdir = Path(tmp)
        jobs = {}
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for impl in IMPLS:
                log(f"== callgrind total: {impl}")
                jobs[("total", impl)] = pool.submit(callgrind_total, binary, impl, args.cycles,
                                                    args.seed, workdir)
                if not args.no_worst:
                    log(f"== callgrind per cycle: {impl} ({args.cycles} dumps)")
                    jobs[("per", impl)] = pool.submit(callgrind_per_cycle, binary, impl,
                                                      args.cycles, args.seed, workdir)
            results = {k: f.result() for k, f in jobs.items()}

    # 4. Report.
    print("SystemStateManager cycle benchmark (valgrind callgrind, instructions = Ir)")
    print(f"binary: {binary}")
    print(f"scenario: {args.cycles} cycles, seed {args.seed}")
    first = native["ssm"].splitlines()
    for line in first[3:]:
        print(f"  {line}")
    print()
    summary = [line for line in cc.strip().splitlines() if line.startswith("crosscheck:")]
    print("cross-check: " + (" / ".join(summary) if summary else cc.strip().splitlines()[0]))  # or the divergence
    if "DIVERGENCE" in cc:
        print(cc)
    print()

    rows = []
    for impl, (label, _) in IMPLS.items():
        total = results[("total", impl)]
        kv = parse_kv(native[impl])
        row = {
            "impl": impl, "label": label, "total": total, "mean": total / args.cycles,
            "heap_construct": int(kv.get("heap_allocations_construction", "-1")),
            "heap_after": int(kv.get("heap_allocations_after_construction", "-1")),
        }
        if not args.no_worst:
            per = results[("per", impl)]
            s = sorted(per)
            row.update({
                "per_sum": sum(per), "min": s[0], "p50": percentile(s, 50),
                "p99": percentile(s, 99), "p999": percentile(s, 99.9), "max": s[-1],
                "argmax": per.index(s[-1]), "stdev": statistics.pstdev(per),
            })
        rows.append(row)

    base = rows[0]
    hdr = f"{'implementation':38} {'mean Ir/cycle':>13} {'worst Ir':>9} {'ratio mean':>10} {'ratio worst':>11} {'heap after ctor':>15}"
    print(hdr)
    print("-" * len(hdr))
    for r in rows:
        worst = r.get("max")
        rw = f"{worst / base['max']:.2f}x" if worst is not None else "n/a"
        print(f"{r['label']:38} {r['mean']:13.1f} {worst if worst is not None else 'n/a':>9} "
              f"{r['mean'] / base['mean']:9.2f}x {rw:>11} {r['heap_after']:>15}")
    print()
    if not args.no_worst:
        print("per-cycle distribution (exact, one callgrind dump per cycle):")
        print(f"{'implementation':38} {'min':>7} {'p50':>7} {'p99':>7} {'p99.9':>7} {'max':>7} {'max at cycle':>12} {'sum check':>10}")
        for r in rows:
            check = "ok" if r["per_sum"] == r["total"] else f"{r['per_sum'] - r['total']:+d}"
            print(f"{r['label']:38} {r['min']:7d} {r['p50']:7d} {r['p99']:7d} {r['p999']:7d} "
                  f"{r['max']:7d} {r['argmax']:12d} {check:>10}")
        print()
        for r in rows:
            print(f"worst cycle of {r['impl']} (cycle {r['argmax']}), replayed natively:")
            print(run_native(binary, ["describe", "--seed", str(args.seed), "--cycle",
                                      str(r["argmax"])]).rstrip())
            print()
    print("heap allocations: construction "
          + ", ".join(f"{r['impl']}={r['heap_construct']}" for r in rows)
          + "; after construction "
          + ", ".join(f"{r['impl']}={r['heap_after']}" for r in rows))
    return 1 if "DIVERGENCE" in cc else 0


if __name__ == "__main__":
    sys.exit(main())
