"""``safestate evidence [--out DIR] [--reuse] [--system NAME ...] [--coverage]`` and
``safestate evidence --verify DIR``.

Builds the certification evidence package: for every registered system (or the ones
named) runs -- or with --reuse takes from build/evidence-cache/ when the inputs are
unchanged -- the model check, the proofs, the conformance, each model mutant, the
GoogleTest tests (ctest) and the pytest tests named after requirement IDs, and writes
DIR/index.html (summary, traceability matrix of every requirement ID, gaps in red),
one page per system (diagrams, proofs, counterexamples), the raw artefacts and
manifest.json (SHA-256 of every input and output, tool versions, machine, date).
Prints the package's path and its gap count.

--verify DIR re-hashes the inputs and outputs and re-runs the model check of each CI
cfg (each stopped after --check-timeout seconds); it prints every difference.

Exit codes: 0 built (or verified) and every step succeeded; 1 a step failed (a check,
proof, conformance, mutant or test; the package is still written, with the failure
in it) / --verify found a difference; 2 usage or input error; 124 --verify found no
difference but a re-run check timed out (not verified).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

from ..errors import run_guarded
from ..systems.registry import registry_dir
from .build import Options, build, find_requirements
from .verify import CHECK_TIMEOUT_SECONDS, verify

TIMED_OUT = 124  # --verify: no difference, but a re-run check reached --check-timeout (as timeout(1))


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--out", default="build/evidence", metavar="DIR", help="the package folder (default build/evidence)")
    p.add_argument("--reuse", action="store_true", help="reuse cached step results whose inputs are unchanged")
    p.add_argument("--system", action="append", default=[], metavar="NAME",
                   help="only this registered system (repeatable; default every system)")
    p.add_argument("--requirements", metavar="FILE", help="REQUIREMENTS.md (default ../shared/, else docs/requirements/)")
    p.add_argument("--conform-args", default="--input-complete --seed 0",
                   help="arguments of each `safestate conform` run (default: %(default)s)")
    p.add_argument("--jobs", type=_jobs, default=None, metavar="N",
                   help="steps run side by side (default: 2, or 1 on a one-core machine)")
    p.add_argument("--no-pytest", action="store_true", help="leave the pytest tests out (GoogleTest still runs)")
    p.add_argument("--no-screenshots", action="store_true", help="no headless-Chromium screenshots")
    p.add_argument("--coverage", action="store_true",
                   help="also gcovr branch coverage of the flagship's C++ under conformance (slow)")
    p.add_argument("--verify", metavar="DIR", help="verify the package DIR instead of building one")
    p.add_argument("--check-timeout", type=_seconds, default=CHECK_TIMEOUT_SECONDS, metavar="SECONDS",
                   help=f"with --verify: stop a re-run model check after this long and report it as timed out "
                   f"(exit 124; default {CHECK_TIMEOUT_SECONDS:g})")
    p.add_argument("--root", metavar="DIR", help="with --verify: the repository whose inputs to re-hash "
                   "(default: the one recorded in the manifest)")


def step_costs(steps: list[dict[str, Any]], top: int = 8) -> list[str]:
    """The slowest steps run (not reused) and what all of them took together: where
    the package's time goes."""
    ran = sorted((s for s in steps if not s["cached"]), key=lambda s: -s["seconds"])
    reused = len(steps) - len(ran)
    out = [f"evidence: {len(ran)} steps run ({sum(s['seconds'] for s in ran):.0f} s of step time), {reused} reused"]
    out += [f"  {s['seconds']:8.1f} s  {s['name']}" for s in ran[:top]]
    return out


def _jobs(text: str) -> int:
    return int(_number(text, int, "a whole number of jobs", 1))


def _seconds(text: str) -> float:
    return _number(text, float, "a number of seconds", 0, strict=True)


def _number(text: str, kind: type[int] | type[float], what: str, low: float, strict: bool = False) -> float:
    """`text` as `kind`, at least `low` (more than `low` when strict), or argparse's error."""
    try:
        n = kind(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected {what}, not {text!r}") from None
    if n < low or (strict and n == low) or n != n:
        raise argparse.ArgumentTypeError(f"must be {'more than' if strict else 'at least'} {low}, not {text}")
    return n


def _log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def run(args: argparse.Namespace) -> int:
    return run_guarded(lambda: _run(args), "evidence", 2)


def _run(args: argparse.Namespace) -> int:
    if args.verify:
        timeouts: list[str] = []
        diffs = verify(Path(args.verify), Path(args.root).resolve() if args.root else None, _log,
                       timeout=args.check_timeout, timeouts=timeouts)
        for d in diffs:
            print(d)
        for t in timeouts:
            print(f"TIMEOUT: {t}")
        if diffs:
            print(f"{args.verify}: {len(diffs)} difference(s)")
            return 1
        if timeouts:
            print(f"{args.verify}: not verified: {len(timeouts)} check(s) timed out")
            return TIMED_OUT
        print(f"{args.verify}: verified, no difference")
        return 0
    root = registry_dir().parent.resolve()
    req = Path(args.requirements) if args.requirements else find_requirements(root)
    if req is None:
        from ..errors import UsageError
        raise UsageError("REQUIREMENTS.md not found (give --requirements FILE or set SAFESTATE_REQUIREMENTS)")
    t0 = time.monotonic()
    res = build(Options(out=Path(args.out).resolve(), root=root, requirements=req.resolve(), systems=args.system,
                        reuse=args.reuse, conform_args=args.conform_args.split(), pytest=not args.no_pytest,
                        screenshots=not args.no_screenshots, coverage=args.coverage, log=_log,
                        **({"jobs": args.jobs} if args.jobs else {})))
    for line in step_costs(res.steps):
        print(line)
    for f in res.failures:
        print(f"FAILED: {f}")
    print(f"evidence package: {res.out}/index.html ({res.gaps} gaps; built in {time.monotonic() - t0:.0f} s)")
    return 1 if res.failures else 0
