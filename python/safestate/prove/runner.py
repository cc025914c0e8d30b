"""Runs the proof of each requested invariant with its engine, and confirms
inconclusive inductions with BMC (a counterexample to induction is a
violation only when BMC reaches it).

Invariants proved by k-induction with the same k and the same strengthening are first
proved together: one induction of their conjunction (Init => Q, Q /\\ Next => Q', Q the
conjunction with the strengthening) proves each of them, at the cost of one proof instead
of one per invariant.  When the joint proof fails, each invariant of the group is proved
on its own, so a failing invariant is still reported by name with its own trace or
counterexample to induction."""

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
from .vacuity import vacuity, vacuity_of_group
from .welldefined import Parts, first_on_trace, failing_under, mark_undefined, parts_of, reach

DEFAULT_DEPTH = {"bmc": 20, "kind": 4, "pdr": 0}
PDR_TIMEOUT = 120.0
CONFIRM_TIMEOUT = 60.0  # seconds of BMC spent confirming an inconclusive proof (deep unrollings get slow)


def prove_all(sys: System, invariants: list[str], plan: Plan, engine: str | None, depth: int | None,
              log: Callable[[str], None]) -> list[Result]:
    results = []
    bmc_batch = []
    kind_groups: dict[tuple[int, tuple[str, ...]], list[str]] = {}
    for inv in invariants:
        step = plan.steps.get(inv, Step(inv))
        eng = engine or step.engine
        if eng == "bmc":
            bmc_batch.append(inv)
        elif eng == "kind":
            kind_groups.setdefault((_kind_depth(step, depth), tuple(step.strengthen)), []).append(inv)
        else:
            results.append(_prove_one(sys, inv, step, eng, depth, log))
    for (k, strengthen), group in kind_groups.items():
        joint = _prove_jointly(sys, group, list(strengthen), k, log) if len(group) > 1 else None
        if joint is not None:
            results.extend(joint)
            continue
        results.extend(_prove_one(sys, inv, plan.steps.get(inv, Step(inv)), "kind", depth, log) for inv in group)
    if bmc_batch:
        k = depth if depth is not None else DEFAULT_DEPTH["bmc"]
        with_obligations = {n: sys.predicate_obligations(n) for n in bmc_batch}
        found = bmc(sys, {n: p for n, (p, _) in with_obligations.items()}, k, log,
                    obligations={n: obligations for n, (_, obligations) in with_obligations.items()})
        for n in bmc_batch:
            results.append(_trace_defined(sys, found[n], parts_of(sys, {n: with_obligations[n][1]})))
    order = {n: i for i, n in enumerate(invariants)}
    return sorted(results, key=lambda r: order[r.invariant])


def _kind_depth(step: Step, depth: int | None) -> int:
    return depth if depth is not None else (step.k or DEFAULT_DEPTH["kind"])


def _strengthening(sys: System, names: list[str]) -> dict[str, z3.BoolRef]:
    return {label: f for n in names for label, f in sys.conjuncts(n).items()}


def _prove_jointly(sys: System, group: list[str], strengthen: list[str], k: int,
                   log: Callable[[str], None]) -> list[Result] | None:
    """One k-induction of the conjunction of `group`, then the well-definedness
    obligations of Init, Next, the invariants and the strengthening checked once for the
    whole group under the joint inductive invariant, and the vacuity of each: a Result
    per invariant when all of that holds, None when not (the caller then proves each
    invariant on its own, which names the failing one with its trace)."""
    t0 = time.monotonic()
    with_obligations = {inv: sys.predicate_obligations(inv) for inv in group}
    first, *rest = group
    strengthening = _strengthening(sys, strengthen)
    res = kinduction(sys, first, with_obligations[first][0],
                     {**{inv: with_obligations[inv][0] for inv in rest}, **strengthening}, k, log)
    if res.status != "proved":
        log(f"joint induction of {len(group)} invariants: {res.status}; proving each on its own")
        return None
    log(f"joint induction of {len(group)} invariants: proved ({time.monotonic() - t0:.1f}s); "
        "well-definedness and vacuity")
    q = z3.And([p for p, _ in with_obligations.values()] + [sys.domain] + list(strengthening.values()))
    parts = parts_of(sys, {**{inv: obligations for inv, (_, obligations) in with_obligations.items()},
                           **{n: sys.predicate_obligations(n)[1] for n in strengthen}})
    failing = failing_under(sys, q, parts)
    if failing:
        log(f"joint induction of {len(group)} invariants: {len(failing)} well-definedness obligation(s) "
            f"fail in the joint invariant (first: {failing[0].describe()}); proving each on its own")
        return None
    vacuous = vacuity_of_group(sys, group, q)
    seconds = time.monotonic() - t0
    note = f"proved in one induction with the {len(group) - 1} other invariants of the same k and strengthening"
    log(f"joint induction of {len(group)} invariants: proved, {parts.count()} well-definedness obligations "
        f"hold ({seconds:.1f}s)")
    results = []
    for inv in group:
        r = Result(inv, "proved", "kind", res.k, seconds, note=note, obligations=parts.count())
        if vacuous[inv]:
            r.status, r.vacuity, r.note = "vacuous", vacuous[inv], "; ".join(vacuous[inv])
        results.append(r)
    return results


def _prove_one(sys: System, inv: str, step: Step, eng: str, depth: int | None, log) -> Result:
    p, obligations = sys.predicate_obligations(inv)
    predicates = {inv: obligations, **{n: sys.predicate_obligations(n)[1] for n in step.strengthen}}
    parts = parts_of(sys, predicates)
    t0 = time.monotonic()
    strengthen = _strengthening(sys, step.strengthen)
    q = z3.And([p, sys.domain] + list(strengthen.values()))
    if eng == "kind":
        res = kinduction(sys, inv, p, strengthen, _kind_depth(step, depth), log)
    else:
        res = pdr(sys, inv, p, step.timeout or PDR_TIMEOUT, log)
    if res.status != "proved" and res.trace is None:
        # inconclusive: is there a real counterexample within the bound?
        k = depth if depth is not None else DEFAULT_DEPTH["bmc"]
        log(f"{inv}: {eng} inconclusive, looking for a counterexample by BMC up to depth {k}")
        b = bmc(sys, {inv: p}, k, log, timeout_s=CONFIRM_TIMEOUT, obligations={inv: obligations})[inv]
        if b.status in ("violated", "ill-defined"):
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
        mark_undefined(sys, res, u, "the trace reaches")
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
            mark_undefined(sys, res, u, "a trace reaches")
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
