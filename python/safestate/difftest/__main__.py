"""``python -m safestate.difftest``: compare `safestate check` with TLC on random
or given specs.  See the package docstring."""

from __future__ import annotations

import argparse
import json
import sys
import time

from ..checker.native.engine_choice import ENGINES
from ..checker.tlc import tlc_jar
from .generator import GRAMMARS
from .runner import Runner, stderr_log


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m safestate.difftest",
                                description="Differential testing of safestate check against TLC "
                                            "(TLC runs only when TLA2TOOLS_JAR names a tla2tools.jar).")
    p.add_argument("--seed", type=int, default=1, help="seed of the generator (default 1)")
    p.add_argument("--count", type=int, default=100, help="number of generated specs (default 100)")
    p.add_argument("--start", type=int, default=0, help="index of the first generated spec (default 0)")
    p.add_argument("--grammar", type=int, choices=GRAMMARS, default=5,
                   help="generator version (default 5; 1-4 reproduce specs of earlier runs)")
    p.add_argument("--specs", metavar="DIR", help="compare on every NAME.tla/NAME.cfg pair below DIR "
                   "instead of generated specs")
    p.add_argument("--out", metavar="DIR", help="write every (minimised) disagreement here")
    p.add_argument("--json", action="store_true", help="print a JSON summary on stdout")
    p.add_argument("--no-minimise", action="store_true", help="do not shrink disagreements")
    p.add_argument("--engine", choices=ENGINES, default="python",
                   help="the engine of safestate check to compare (default python; native refuses what "
                        "the core does not accept, auto falls back to python there)")
    p.add_argument("--timeout", type=float, default=120, help="seconds per spec and checker (default 120)")
    p.add_argument("--progress", type=int, default=50, metavar="N", help="a progress line every N specs")
    args = p.parse_args(argv)
    jar = tlc_jar()
    if jar is None:
        stderr_log("TLA2TOOLS_JAR is not set to an existing tla2tools.jar: the comparison with TLC is "
                   "skipped; each spec is only checked by safestate (internal errors are reported).")
    start = time.monotonic()
    runner = Runner(jar, args.out, not args.no_minimise, args.timeout, stderr_log, args.engine)
    try:
        if args.specs:
            runner.run_dir(args.specs, args.progress)
        else:
            runner.run_generated(args.seed, args.count, args.start, args.progress, args.grammar)
    finally:
        runner.close()
    t = runner.tally
    summary = {"tlc": jar is not None, "engine": args.engine, "seed": None if args.specs else args.seed,
               "grammar": None if args.specs else args.grammar, "specs": t.specs,
               "agree": t.agree, "refused": t.refused, "disagree": t.disagree, "timeouts": t.timeouts,
               "crashes": t.crashes, "refusals": t.refusals, "tlc_results": t.results,
               "features": t.features, "seconds": round(time.monotonic() - start, 1),
               "disagreements": [{k: d[k] for k in ("name", "fields", "detail") if k in d}
                                 | ({"repro": d["repro"]} if "repro" in d else {}) for d in t.disagreements]}
    if args.json:
        print(json.dumps(summary, indent=1))
    else:
        stderr_log(f"{t.specs} specs: {t.agree} agree, {t.refused} refused (unsupported), {t.disagree} "
                   f"disagree, {t.timeouts} timeouts, {t.crashes} crashes ({summary['seconds']} s)")
    return 1 if t.disagree or t.crashes else 0


if __name__ == "__main__":
    sys.exit(main())
