"""Bounded model checking: Init /\\ Next^k /\\ ~P at step k, for k = 0, 1, ...

Depths are tried in increasing order, so the first counterexample found for an
invariant is a shortest one (in steps of Next).  At each depth one query asks
whether any open invariant fails; only when one does are the failing ones
picked out of the model (and the query repeated for the others).
"""

from __future__ import annotations

import time
from typing import Callable

import z3

from ..system import System
from .result import Result


def bmc(sys: System, props: dict[str, z3.BoolRef], depth: int, log: Callable[[str], None] = lambda s: None,
        timeout_s: float | None = None) -> dict[str, Result]:
    t0 = time.monotonic()
    s = sys.solver(*props.values())
    s.add(sys.assumptions)
    s.add(sys.init_at(0))
    results: dict[str, Result] = {}
    open_ = dict(props)
    reached = -1
    # A step that assigns a structured variable a value outside its TypeOK domain cannot
    # be represented (the step would simply be missing): its 'type' obligation is checked
    # on the step out of each depth's last state instead (docs/prove.md).
    type_inv = sys.tr.type_invariant
    type_obligations = [o for o in sys.trans_obligations if o.kind == "type"] if type_inv in props else []
    for k in range(depth + 1):
        if k > 0:
            if type_inv in open_ and type_obligations:
                _type_step(sys, s, type_obligations, k - 1, results, t0)
                if type_inv in results:
                    del open_[type_inv]
            s.add(sys.trans_at(k - 1))
        while open_:
            at_k = {n: sys.at(p, k) for n, p in open_.items()}
            s.push()
            s.add(z3.Not(z3.And(list(at_k.values()))))
            r = s.check()
            if r != z3.sat:
                s.pop()
                break
            m = s.model()
            trace = [sys.state_values(m, i) for i in range(k + 1)]
            params = sys.param_values(m)
            for n, f in at_k.items():
                if z3.is_false(m.eval(f, model_completion=True)):
                    results[n] = Result(n, "violated", "bmc", k, time.monotonic() - t0, trace=trace, params=params,
                                        model=m)
                    del open_[n]
            s.pop()
        reached = k
        log(f"bmc: depth {k} done ({time.monotonic() - t0:.1f}s), {len(open_)} invariant(s) hold so far")
        if not open_ or (timeout_s is not None and time.monotonic() - t0 > timeout_s):
            break
    for name in open_:
        results[name] = Result(name, "unknown", "bmc", reached, time.monotonic() - t0,
                               note=f"no counterexample up to depth {reached}")
    return results


def _type_step(sys: System, s: z3.Solver, obligations: list, i: int, results: dict[str, Result],
               t0: float) -> None:
    """From a reached state i, a step whose assignment leaves TypeOK's domain: the type
    invariant is violated in the state after it (not shown: it is not representable)."""
    conds = [sys.trans_at(i, o.cond) for o in obligations]  # one substitution each, queried and read back
    s.push()
    s.add(z3.Not(z3.And(conds)))
    if s.check() == z3.sat:
        m = s.model()
        failing = next(o for o, c in zip(obligations, conds) if z3.is_false(m.eval(c, model_completion=True)))
        name = sys.tr.type_invariant
        results[name] = Result(name, "violated", "bmc", i + 1, time.monotonic() - t0,
                               trace=[sys.state_values(m, j) for j in range(i + 1)], params=sys.param_values(m),
                               model=m, undefined=f"{failing.where()}: in Next, type obligation fails: {failing.what}",
                               note=f"the next step leaves {name}'s domain; the state after it is not representable "
                                    f"and is not shown")
    s.pop()
