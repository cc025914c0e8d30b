"""The C++ mutant kill table: which realistic C++ mistakes (mutants.toml) conformance
catches -- the trace replay of every reachable transition of the CI cfg, and the
input-complete pass -- and which GoogleTest catches.

    .venv/bin/python conform/cpp_mutants/kill_table.py BUILD_DIR [--no-gtest]
        [--only ID ...] [--json FILE] [--gtest-only]

Builds every mutant (mutate.py, one CMake tree), then per mutant runs the input-complete
pass (stopping at the first mismatch), the trace replay of every transition (likewise;
only when the input-complete pass did not kill it, unless --always-replay) and, unless
--no-gtest, every GoogleTest executable built against the mutant.  Prints a Markdown
table.  Takes long (a surviving mutant costs a full replay and a full input-complete
pass); the test suite runs a subset (tests/python/test_conform_input_complete.py).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from mutate import REPO, Mutant, build_all, load  # noqa: E402

from safestate.checker.model import load_model  # noqa: E402
from safestate.conform import conformance, graph as graph_mod  # noqa: E402
from safestate.conform.cli import make_harness  # noqa: E402
from safestate.conform.input_complete import run_input_complete  # noqa: E402
from safestate.systems.registry import find  # noqa: E402


def gtest_kills(build: Path, m: Mutant) -> tuple[bool, list[str]]:
    failed = []
    for exe in sorted((build / f"gtest_{m.id}").glob("test_*")):
        r = subprocess.run([str(exe), "--gtest_brief=1"], capture_output=True, text=True, timeout=600)
        if r.returncode != 0:
            failed.append(exe.name)
    return bool(failed), failed


def measure(build: Path, mutants: list[Mutant], gtest: bool, log=print,  # type: ignore[no-untyped-def]
            always_replay: bool = False) -> list[dict]:
    system = find("SystemStateManager", REPO / "systems")
    assert system is not None
    model = load_model(str(system.model), str(system.ci_config))
    graph = graph_mod.cached_explore(model)
    if str(build) not in sys.path:
        sys.path.insert(0, str(build))
    rows = []
    for m in mutants:
        module = f"safestate_mut_{m.id}._core"
        t0 = time.monotonic()
        ic = run_input_complete(make_harness(system, model, module), graph)
        t1 = time.monotonic()
        replay_kill: bool | None = None
        replay_steps = 0
        first = ic.mismatch.splitlines()[0] if ic.mismatch else None
        if always_replay or ic.mismatch is None:
            h = make_harness(system, model, module)
            with tempfile.TemporaryDirectory() as tmp:
                res = conformance.run(model, h.core, graph, h,
                                      conformance.Options(reproducer_dir=tmp, max_mismatches=1))
            replay_kill, replay_steps = bool(res.found), res.steps
            if res.found:
                first = res.found[0].mismatch.render().splitlines()[0]
        t2 = time.monotonic()
        row = {"id": m.id, "kind": m.kind, "what": m.what, "replay": replay_kill, "replay_steps": replay_steps,
               "input_complete": ic.mismatch is not None, "input_complete_probes": ic.probes,
               "input_complete_s": round(t1 - t0, 1), "replay_s": round(t2 - t1, 1), "first_mismatch": first}
        if gtest:
            row["gtest"], row["gtest_failed"] = gtest_kills(build, m)
        rows.append(row)
        log(json.dumps(row))
    return rows


def table(rows: list[dict]) -> str:
    def yn(b: bool | None) -> str:
        return "-" if b is None else "yes" if b else "no"
    out = ["| mutant | kind | trace replay | input-complete | conformance | GoogleTest |",
           "|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| `{r['id']}` | {r['kind']} | {yn(r['replay'])} | {yn(r['input_complete'])} | "
                   f"{yn(r['replay'] or r['input_complete'])} | {yn(r.get('gtest'))} |")
    killed = sum(1 for r in rows if r["replay"] or r["input_complete"])
    out.append(f"\nconformance kills {killed}/{len(rows)} ({100 * killed / max(len(rows), 1):.0f}%) "
               f"(trace replay '-': not run, the input-complete pass had killed it; --always-replay runs it)")
    if any("gtest" in r for r in rows):
        g = sum(1 for r in rows if r.get("gtest"))
        out.append(f"GoogleTest kills {g}/{len(rows)}")
    return "\n".join(out)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build", type=Path)
    ap.add_argument("--no-gtest", action="store_true")
    ap.add_argument("--only", nargs="+", metavar="ID")
    ap.add_argument("--json", type=Path)
    ap.add_argument("--always-replay", action="store_true",
                    help="run the trace replay also on mutants the input-complete pass killed")
    ap.add_argument("--gtest-only", action="store_true",
                    help="the GoogleTest column only (no conformance pass: seconds per mutant)")
    ap.add_argument("-j", "--jobs", type=int, default=1)
    a = ap.parse_args()
    mutants = [m for m in load() if not a.only or m.id in a.only]
    build = a.build.resolve()
    build_all(build, mutants, gtest=not a.no_gtest, jobs=a.jobs)
    if a.gtest_only:
        for m in mutants:
            killed, failed = gtest_kills(build, m)
            print(f"| `{m.id}` | {'yes: ' + ', '.join(failed) if killed else 'no'} |", flush=True)
        return 0
    rows = measure(build, mutants, not a.no_gtest, log=lambda s: print(s, file=sys.stderr, flush=True),
                   always_replay=a.always_replay)
    if a.json:
        a.json.write_text(json.dumps(rows, indent=1) + "\n", encoding="utf-8")
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
