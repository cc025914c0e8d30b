"""k-induction with strengthening invariants.

Q = P /\\ the TypeOK domains /\\ the strengthening invariants.  For k = 1, 2, ...:
base: no state reachable in fewer than k steps violates Q (BMC); step:
Q at k consecutive states linked by Next implies Q at the next one.  A failed
step leaves a counterexample to induction (two states), which is reported, not
taken for a violation: only the base case (a real trace) makes P violated.
"""

from __future__ import annotations

import time
from typing import Callable

import z3

from ..system import System
from .result import Result


def kinduction(sys: System, name: str, prop: z3.BoolRef, strengthen: dict[str, z3.BoolRef], depth: int,
               log: Callable[[str], None] = lambda s: None) -> Result:
    t0 = time.monotonic()
    parts = {name: prop, "TypeOK domains": sys.domain, **strengthen}
    q = z3.And(list(parts.values()))
    base = sys.solver(q)
    base.add(sys.assumptions, sys.init_at(0))
    step = sys.solver(q)
    step.add(sys.assumptions)
    last_model = None
    for k in range(1, depth + 1):
        # base case: Q holds in every state reachable in k-1 steps
        if k > 1:
            base.add(sys.trans_at(k - 2))
        base.push()
        base.add(z3.Not(sys.at(q, k - 1)))
        if base.check() == z3.sat:
            m = base.model()
            trace = [sys.state_values(m, i) for i in range(k)]
            failed = [n for n, f in parts.items() if z3.is_false(m.eval(sys.at(f, k - 1), model_completion=True))]
            base.pop()
            if name in failed:
                return Result(name, "violated", "kind", k - 1, time.monotonic() - t0, trace=trace,
                              params=sys.param_values(m), model=m)
            return Result(name, "unknown", "kind", k - 1, time.monotonic() - t0, trace=None,
                          note=f"strengthening {', '.join(failed)} is violated by a reachable state "
                               f"(depth {k - 1}): it is not an invariant")
        base.pop()
        # inductive step
        step.add(sys.at(q, k - 1), sys.trans_at(k - 1))
        step.push()
        step.add(z3.Not(sys.at(q, k)))
        r = step.check()
        log(f"kind {name}: k={k} step {r} ({time.monotonic() - t0:.1f}s)")
        if r == z3.unsat:
            step.pop()
            return Result(name, "proved", "kind", k, time.monotonic() - t0)
        if r == z3.sat:
            last_model = (step.model(), k)
        step.pop()
    res = Result(name, "unknown", "kind", depth, time.monotonic() - t0)
    if last_model is not None:
        m, k = last_model
        res.cti = [sys.state_values(m, k - 1), sys.state_values(m, k)]
        res.cti_params = sys.param_values(m)
        failed = [n for n, f in parts.items() if z3.is_false(m.eval(sys.at(f, k), model_completion=True))]
        res.note = f"induction step fails at k={k}: the successor state violates {', '.join(failed)}"
    return res
