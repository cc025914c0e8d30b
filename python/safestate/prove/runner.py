"""Runs the proof of each requested invariant with its engine, and confirms
inconclusive inductions with BMC (a counterexample to induction is a
violation only when BMC reaches it)."""

from __future__ import annotations

import time
from typing import Callable

from .engines.bmc import bmc
from .engines.kind import kinduction
from .engines.pdr import pdr
from .engines.result import Result
from .plan import Plan, Step
from .system import System

DEFAULT_DEPTH = {"bmc": 20, "kind": 4, "pdr": 0}
PDR_TIMEOUT = 120.0
CONFIRM_TIMEOUT = 60.0  # seconds of BMC spent confirming an inconclusive proof (deep unrollings get slow)


def prove_all(sys: System, invariants: list[str], plan: Plan, engine: str | None, depth: int | None,
              log: Callable[[str], None]) -> list[Result]:
    results = []
    bmc_batch = []
    for inv in invariants:
        step = plan.steps.get(inv, Step(inv))
        eng = engine or step.engine
        if eng == "bmc":
            bmc_batch.append(inv)
            continue
        results.append(_prove_one(sys, inv, step, eng, depth, log))
    if bmc_batch:
        k = depth if depth is not None else DEFAULT_DEPTH["bmc"]
        props = {n: sys.predicate(n) for n in bmc_batch}
        found = bmc(sys, props, k, log)
        results.extend(found[n] for n in bmc_batch)
    order = {n: i for i, n in enumerate(invariants)}
    return sorted(results, key=lambda r: order[r.invariant])


def _prove_one(sys: System, inv: str, step: Step, eng: str, depth: int | None, log) -> Result:
    p = sys.predicate(inv)
    t0 = time.monotonic()
    if eng == "kind":
        k = depth if depth is not None else (step.k or DEFAULT_DEPTH["kind"])
        strengthen = {label: f for n in step.strengthen for label, f in sys.conjuncts(n).items()}
        res = kinduction(sys, inv, p, strengthen, k, log)
    else:
        res = pdr(sys, inv, p, step.timeout or PDR_TIMEOUT, log)
    if res.status != "proved" and res.trace is None:
        # inconclusive: is there a real counterexample within the bound?
        k = depth if depth is not None else DEFAULT_DEPTH["bmc"]
        log(f"{inv}: {eng} inconclusive, looking for a counterexample by BMC up to depth {k}")
        b = bmc(sys, {inv: p}, k, log, timeout_s=CONFIRM_TIMEOUT)[inv]
        if b.status == "violated":
            b.engine = f"{eng}+bmc"
            b.cti, b.cti_params = res.cti, res.cti_params
            res = b
        else:
            if res.status == "violated":
                res.status = "unknown"
            res.note += f"; BMC found no counterexample up to depth {b.k}"
    res.seconds = time.monotonic() - t0
    return res
