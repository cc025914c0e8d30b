#!/usr/bin/env python3
"""Benchmark of the search on Ray (`safestate check --ray local`) against the plain search,
in the same run: the overhead of distribution as a ratio.

For each spec, four runs of `safestate check --engine python --json` (a fresh process
each): one worker; two forked workers (`--workers 2`); and on a local Ray cluster started
by the run, one and two actors (`--ray local --workers N`).  The plain run's search CPU
is the child process's user+system time (os.wait4) less that of a process that only
starts and loads the model; a sharded run's is its critical path as `--json` reports it
(the slowest worker's CPU per BFS phase summed, plus the coordinator's): the time it
would take on idle cores, whatever the load.  Printed per run: distinct and generated
states, wall seconds, search CPU seconds, states generated per CPU second, and that rate
over the plain run's.  Informational only: never pass/fail.

usage: bench/bench_ray.py [SPEC.tla[:CFG] ...]   (default: Protection and RuntimeSupervisor)
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DEFAULT = ["models/Protection.tla", "models/RuntimeSupervisor.tla"]
RUNS = [("plain, 1 worker", []), ("forked, 2 workers", ["--workers", "2"]),
        ("Ray, 1 actor", ["--ray", "local", "--workers", "1"]), ("Ray, 2 actors", ["--ray", "local", "--workers", "2"])]


def _child(argv: list[str]) -> tuple[str, float, float]:
    """(stdout, wall seconds, CPU seconds) of one child process."""
    t0 = time.monotonic()
    p = subprocess.Popen(argv, cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    out = p.stdout.read() if p.stdout else ""
    _, _, usage = os.wait4(p.pid, 0)
    return out, time.monotonic() - t0, usage.ru_utime + usage.ru_stime


def load_cpu(spec: str) -> float:
    """CPU seconds to start Python and load the model, the part of a plain run that is not search."""
    tla, _, cfg = spec.partition(":")
    code = f"from safestate.checker.model import load_model; load_model({tla!r}, {cfg or None!r})"
    return _child([sys.executable, "-c", code])[2]


def run(spec: str, extra: list[str], loading: float) -> tuple[dict, float, float]:
    tla, _, cfg = spec.partition(":")
    argv = [sys.executable, "-m", "safestate.cli", "check", tla, "--engine", "python", "--json", *extra]
    if cfg:
        argv += ["--config", cfg]
    out, wall, cpu = _child(argv)
    j = json.loads(out)
    par = j.get("parallel")
    return j, wall, par["critical_path_cpu_seconds"] if par else max(cpu - loading, 1e-3)


def main(specs: list[str]) -> int:
    print(f"{'spec':20} {'run':18} {'distinct':>9} {'generated':>10} {'wall s':>7} {'CPU s':>7} "
          f"{'gen./CPU s':>11} {'x plain':>7}")
    for spec in specs:
        loading = load_cpu(spec)
        base = 0.0
        for name, extra in RUNS:
            j, wall, cpu = run(spec, extra, loading)
            rate = j["states_generated"] / cpu
            base = base or rate
            print(f"{Path(spec.split(':')[0]).stem:20} {name:18} {j['distinct_states']:>9,} {j['states_generated']:>10,} "
                  f"{wall:>7.1f} {cpu:>7.2f} {rate:>11,.0f} {rate / base:>7.2f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or DEFAULT))
