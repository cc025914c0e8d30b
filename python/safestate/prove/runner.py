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
        props = {n: sys.predicate(n) for n in bmc_batch}
        found = bmc(sys, props, k, log)
        results.extend(found[n] for n in bmc_batch)
    order = {n: i for i, n in enumerate(invariants)}
    return sorted(results, key=lambda r: order[r.invariant])


def _kind_depth(step: Step, depth: int | None) -> int:
    return depth if depth is not None else (step.k or DEFAULT_DEPTH["kind"])


def _strengthening(sys: System, names: list[str]) -> dict[str, z3.BoolRef]:
    return {label: f for n in names for label, f in sys.conjuncts(n).items()}


def _prove_jointly(sys: System, group: list[str], strengthen: list[str], k: int,
                   log: Callable[[str], None]) -> list[Result] | None:
    """One k-induction of the conjunction of `group`: a Result per invariant when it is
    proved, None when it is not (the caller then proves each invariant on its own)."""
    t0 = time.monotonic()
    first, *rest = group
    others = {inv: sys.predicate(inv) for inv in rest}
    res = kinduction(sys, first, sys.predicate(first), {**others, **_strengthening(sys, strengthen)}, k, log)
    if res.status != "proved":
        log(f"joint induction of {len(group)} invariants: {res.status}; proving each on its own")
        return None
    seconds = time.monotonic() - t0
    note = f"proved in one induction with the {len(group) - 1} other invariants of the same k and strengthening"
    log(f"joint induction of {len(group)} invariants: proved ({seconds:.1f}s)")
    return [Result(inv, "proved", "kind", res.k, seconds, note=note) for inv in group]


def _prove_one(sys: System, inv: str, step: Step, eng: str, depth: int | None, log) -> Result:
    p = sys.predicate(inv)
    t0 = time.monotonic()
    if eng == "kind":
        res = kinduction(sys, inv, p, _strengthening(sys, step.strengthen), _kind_depth(step, depth), log)
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
