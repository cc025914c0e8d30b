"""Bounded model checking: Init /\\ Next^k /\\ ~P at step k, for k = 0, 1, ...

Depths are tried in increasing order, so the first counterexample found for an
invariant is a shortest one (in steps of Next).  At each depth one query asks
whether any open invariant fails; only when one does are the failing ones
picked out of the model (and the query repeated for the others).

Every well-definedness obligation evaluated on the explored steps is checked too (TLC
stops with an evaluation error there): Init's at depth 0, the open invariants' in the
depth's last state, and Next's on the step out of it.  A failing one makes every open
invariant `ill-defined` with the trace to the site -- except a 'type' obligation (a
step whose assignment leaves TypeOK's domain, which the translation cannot represent:
the step would simply be missing), which is a violation of the type invariant
(docs/prove.md).
"""

from __future__ import annotations

import time
from typing import Callable

import z3

from ..obligations import Obligation
from ..system import System
from ..welldefined import Parts, mark_undefined, undefined_at
from .result import Result


def bmc(sys: System, props: dict[str, z3.BoolRef], depth: int, log: Callable[[str], None] = lambda s: None,
        timeout_s: float | None = None, obligations: dict[str, list[Obligation]] | None = None
        ) -> dict[str, Result]:
    """`obligations`: those of evaluating each invariant of `props` (none given: none)."""
    t0 = time.monotonic()
    s = sys.solver(*props.values())
    s.add(sys.assumptions)
    s.add(sys.init_at(0))
    results: dict[str, Result] = {}
    open_ = dict(props)
    reached = -1
    type_inv = sys.tr.type_invariant
    # the type obligations only matter to the type invariant: without it they are left out
    trans = [o for o in sys.trans_obligations if o.kind != "type" or type_inv in props]
    for k in range(depth + 1):
        if k > 0:
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
        trans = _undefined_step(sys, s, k, open_, results, trans, obligations or {}, t0)
        reached = k
        log(f"bmc: depth {k} done ({time.monotonic() - t0:.1f}s), {len(open_)} invariant(s) hold so far")
        if not open_ or (timeout_s is not None and time.monotonic() - t0 > timeout_s):
            break
    for name in open_:
        results[name] = Result(name, "unknown", "bmc", reached, time.monotonic() - t0,
                               note=f"no counterexample up to depth {reached}")
    return results


def _undefined_step(sys: System, s: z3.Solver, k: int, open_: dict[str, z3.BoolRef], results: dict[str, Result],
                    trans: list[Obligation], obligations: dict[str, list[Obligation]], t0: float
                    ) -> list[Obligation]:
    """The obligations evaluated at depth k (Init's at 0, the open invariants' in state k,
    Next's out of state k): a failing type obligation violates the type invariant (its
    type obligations are then dropped); a failing one of Init or Next makes every open
    invariant ill-defined, one of an invariant that invariant (and any other evaluating
    the same site); the others are asked again.  Returns Next's obligations still to check."""
    type_inv = sys.tr.type_invariant
    if type_inv not in open_:
        trans = [o for o in trans if o.kind != "type"]
    while open_:
        parts = Parts(sys.init_obligations if k == 0 else [], trans,
                      {n: obligations.get(n, []) for n in open_})
        u = undefined_at(sys, s, parts, k)
        if u is None:
            break
        if u.obligation.kind == "type":
            hit = [type_inv]
        elif u.part in ("Init", "Next"):  # TLC stops exploring: every open invariant ends there
            hit = list(open_)
        else:  # an invariant's own evaluation: the invariants that evaluate this site
            hit = [n for n in open_ if any(o.cond.eq(u.obligation.cond) for o in obligations.get(n, []))]
        for n in hit:
            steps = len(u.trace or [{}]) - (0 if u.part == "Next" else 1)  # Next's: the step out of the last state
            res = Result(n, "unknown", "bmc", steps, time.monotonic() - t0)
            mark_undefined(sys, res, u, "a trace reaches")
            results[n] = res
            del open_[n]
        if u.obligation.kind == "type":
            trans = [o for o in trans if o.kind != "type"]
    return trans
