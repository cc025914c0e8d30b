"""Runs the proof of each requested invariant with its engine, and confirms
inconclusive inductions with BMC (a counterexample to induction is a
violation only when BMC reaches it)."""

from __future__ import annotations

import time
from typing import Callable

import z3

from .engines.bmc import bmc
from .engines.kind import kinduction
from .engines.pdr import pdr
from .engines.result import Result
from .plan import Plan, Step
from .system import System
from .vacuity import vacuity
from .welldefined import Parts, first_on_trace, failing_under, parts_of, reach

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
        with_obligations = {n: sys.predicate_obligations(n) for n in bmc_batch}
        found = bmc(sys, {n: p for n, (p, _) in with_obligations.items()}, k, log)
        for n in bmc_batch:
            results.append(_trace_defined(sys, found[n], parts_of(sys, {n: with_obligations[n][1]})))
    order = {n: i for i, n in enumerate(invariants)}
    return sorted(results, key=lambda r: order[r.invariant])


def _prove_one(sys: System, inv: str, step: Step, eng: str, depth: int | None, log) -> Result:
    p, obligations = sys.predicate_obligations(inv)
    predicates = {inv: obligations, **{n: sys.predicate_obligations(n)[1] for n in step.strengthen}}
    parts = parts_of(sys, predicates)
    t0 = time.monotonic()
    strengthen = {label: f for n in step.strengthen for label, f in sys.conjuncts(n).items()}
    q = z3.And([p, sys.domain] + list(strengthen.values()))
    if eng == "kind":
        k = depth if depth is not None else (step.k or DEFAULT_DEPTH["kind"])
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
    res.obligations = parts.count()
    res = _trace_defined(sys, res, parts)
    if res.status == "proved":
        res = _defined_and_not_vacuous(sys, res, q, parts, depth, log)
    res.seconds = time.monotonic() - t0
    return res


def _trace_defined(sys: System, res: Result, parts: Parts) -> Result:
    """A counterexample that goes through an ill-defined evaluation is not one: the
    spec is ill-defined there (TLC would stop with an evaluation error)."""
    if res.trace is None or res.model is None:
        return res
    u = first_on_trace(sys, res.model, len(res.trace) - 1, parts)
    if u is not None:
        res.status, res.undefined, res.trace, res.params = "ill-defined", u.describe(), u.trace, u.params
        res.note = "the trace reaches an evaluation TLA+ leaves undefined (TLC stops with an error there)"
    return res


def _defined_and_not_vacuous(sys: System, res: Result, q: z3.BoolRef, parts: Parts, depth: int | None,
                             log: Callable[[str], None]) -> Result:
    """A proof holds only with its well-definedness obligations (in every state of the
    inductive invariant Q) and when it is not vacuous."""
    failing = failing_under(sys, q, parts)
    if failing:
        k = depth if depth is not None else DEFAULT_DEPTH["bmc"]
        log(f"{res.invariant}: {len(failing)} well-definedness obligation(s) fail in the invariant; "
            f"looking for a trace up to depth {k}")
        u = reach(sys, parts, k, CONFIRM_TIMEOUT)
        if u is not None:
            res.status, res.undefined, res.trace, res.params = "ill-defined", u.describe(), u.trace, u.params
            res.note = "a trace reaches an evaluation TLA+ leaves undefined (TLC stops with an error there)"
            return res
        first = failing[0]
        res.status = "unknown"
        res.undefined = first.describe()
        res.cti, res.cti_params = [first.state or {}], first.params
        res.note = (f"well-definedness not proved: {first.describe()} in a state of the inductive invariant "
                    f"(none found on a trace up to depth {k}; strengthen the invariant)")
        return res
    res.vacuity = vacuity(sys, res.invariant, q)
    if res.vacuity:
        res.status = "vacuous"
        res.note = "; ".join(res.vacuity)
    return res
