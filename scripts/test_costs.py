#!/usr/bin/env python3
"""Reads the per-test costs recorded by a pytest run with SAFESTATE_TEST_COSTS=FILE
(tests/python/cost_record.py) and prints where the time goes: the dearest tests and the
total per file.  With --write it also writes tests/python/test_costs.json, the CPU
seconds per test that the test command's scheduler uses to hand out the longest work
first (tests/python/cost_schedule.py).

    SAFESTATE_TEST_COSTS=/tmp/costs.jsonl bash scripts/test.sh
    .venv/bin/python scripts/test_costs.py /tmp/costs.jsonl [--top 30] [--write]
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import defaultdict
from pathlib import Path

OUT = Path(__file__).resolve().parents[1] / "tests" / "python" / "test_costs.json"


def read(path: Path) -> dict[str, tuple[float, float]]:
    """(wall, cpu) seconds per node id (a test recorded twice: the last line)."""
    out: dict[str, tuple[float, float]] = {}
    for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        try:
            rec = json.loads(line)
            out[rec["test"]] = (float(rec["wall"]), float(rec["cpu"]))
        except (ValueError, KeyError, TypeError) as e:
            raise SystemExit(f"error: {path}:{n}: not a cost record ({e})") from None
    return out


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("costs", type=Path, help="the JSON-lines file SAFESTATE_TEST_COSTS named")
    ap.add_argument("--top", type=int, default=30, help="how many of the dearest tests to list")
    ap.add_argument("--write", action="store_true", help=f"write {OUT.name}")
    args = ap.parse_args(argv)
    costs = read(args.costs)
    if not costs:
        print(f"error: {args.costs}: no cost records", file=sys.stderr)
        return 2
    print(f"{len(costs)} tests, CPU {sum(c for _, c in costs.values()):.0f} s, "
          f"wall {sum(w for w, _ in costs.values()):.0f} s (summed over workers)")
    print(f"\n| CPU s | wall s | test (the {args.top} dearest) |\n|---:|---:|---|")
    for test, (wall, cpu) in sorted(costs.items(), key=lambda kv: -kv[1][1])[:args.top]:
        print(f"| {cpu:.1f} | {wall:.1f} | `{test}` |")
    per_file: dict[str, list[float]] = defaultdict(lambda: [0, 0.0, 0.0])
    for test, (wall, cpu) in costs.items():
        f = per_file[test.split("::", 1)[0]]
        f[0] += 1
        f[1] += wall
        f[2] += cpu
    print("\n| CPU s | wall s | tests | file |\n|---:|---:|---:|---|")
    for name, (n, wall, cpu) in sorted(per_file.items(), key=lambda kv: -kv[1][2]):
        print(f"| {cpu:.1f} | {wall:.1f} | {n:.0f} | `{name.removeprefix('tests/python/')}` |")
    if args.write:
        OUT.write_text(json.dumps({t: round(c, 2) for t, (_, c) in sorted(costs.items())}, indent=0) + "\n",
                       encoding="utf-8")
        print(f"\nwrote {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
