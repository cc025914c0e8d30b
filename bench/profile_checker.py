#!/usr/bin/env python3
"""Profile of `safestate check`: where the CPU time of the breadth-first search goes.

Runs the search under cProfile until `--max-states` distinct states (or the end),
then groups the functions' own time (tottime) by the part of the checker they
belong to: evaluation of the spec (tla/compiler.py, tla/compile/, tla/stdlib.py), successor
construction (tla/actions.py), value hashing and equality (tla/values.py: the
fingerprint of a state is Python's hash of the state tuple), the search loop and
its seen-set/queue (checker/explore.py, dict and list builtins), and the rest.
Informational only (docs/checker-performance.md quotes its output).

usage: bench/profile_checker.py SPEC.tla [--config CFG] [--max-states N] [--top K]
"""

from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "python"))

from safestate.checker.deep_stack import call_with_deep_stack  # noqa: E402
from safestate.checker.explore import Explorer, _Stop  # noqa: E402
from safestate.checker.model import load_model  # noqa: E402

# (label, test on "file:function") in priority order; the first match wins.
CATEGORIES: list[tuple[str, tuple[str, ...]]] = [
    ("hashing/equality (tla/values.py __hash__/__eq__)", ("values.py:__hash__", "values.py:__eq__",
                                                          "values.py:__ne__", "built-in method builtins.hash")),
    ("successor construction (tla/actions.py)", ("actions.py:",)),
    ("evaluation (tla/compiler.py, compile/, stdlib.py, values.py)", ("compiler.py:", "compile/", "stdlib.py:",
                                                                     "values.py:", "constfold.py:", "specialise.py:")),
    ("seen-set + queue + counting (checker/explore.py)", ("explore.py:",)),
    ("dict/list/array builtins (seen-set lookups, queue appends)", ("method 'get' of 'dict'",
                                                                   "method 'append'")),
    ("model glue (checker/model.py)", ("model.py:",)),
]


class CappedExplorer(Explorer):
    """Stops the search (as a finished one) after `cap` distinct states."""

    cap = 0

    def _periodic(self) -> None:
        super()._periodic()
        if self.cap and len(self.states) >= self.cap:
            raise _Stop()


def categorise(stats: pstats.Stats) -> dict[str, float]:
    out: dict[str, float] = {label: 0.0 for label, _ in CATEGORIES}
    out["other"] = 0.0
    for (file, _line, func), (_cc, _nc, tottime, _ct, _callers) in stats.stats.items():  # type: ignore[attr-defined]
        # "folder/file.py:function": the folder tells tla/compile/'s family modules apart.
        key = f"{os.path.basename(os.path.dirname(file))}/{os.path.basename(file)}:{func}"
        for label, tests in CATEGORIES:
            if any(t in key for t in tests):
                out[label] += tottime
                break
        else:
            out["other"] += tottime
    return out


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("spec")
    ap.add_argument("--config")
    ap.add_argument("--max-states", type=int, default=300_000)
    ap.add_argument("--top", type=int, default=15)
    args = ap.parse_args()
    model = load_model(args.spec, args.config)
    CappedExplorer.cap = args.max_states
    CappedExplorer.next_check = 0
    explorer = CappedExplorer(model, False, None, None)
    cpu0, wall0 = time.process_time(), time.monotonic()
    explorer.run()  # unprofiled reference run: the CPU rate without profiler overhead
    cpu = time.process_time() - cpu0
    n = len(explorer.states)
    print(f"{Path(args.spec).stem}: {n} distinct, {explorer.generated} generated, depth {explorer.max_level}, "
          f"{cpu:.2f} s CPU ({time.monotonic() - wall0:.2f} s wall), {n / cpu:.0f} distinct/CPU s, "
          f"{explorer.generated / cpu:.0f} generated/CPU s")
    explorer = CappedExplorer(model, False, None, None)
    prof = cProfile.Profile(time.process_time)  # CPU time: the machine is shared
    call_with_deep_stack(lambda: prof.runcall(explorer.run))  # the search runs in a big-stack thread
    stats = pstats.Stats(prof)
    total = sum(v[2] for v in stats.stats.values())  # type: ignore[attr-defined]
    print(f"profiled: {total:.2f} s own time in total")
    for label, secs in sorted(categorise(stats).items(), key=lambda kv: -kv[1]):
        print(f"  {100 * secs / total:5.1f}%  {secs:7.2f} s  {label}")
    stats.sort_stats("tottime").print_stats(args.top)
    return 0


if __name__ == "__main__":
    sys.exit(main())
