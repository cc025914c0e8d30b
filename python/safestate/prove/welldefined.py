"""Proving the well-definedness obligations (obligations.py) alongside an invariant.

An invariant's proof covers the states of Q (the invariant, TypeOK's domains and the
strengthening invariants), which include every reachable state once Q is shown
inductive.  The obligations of Init must hold under the ASSUMEs; those of Next and of the
predicates (the invariant and its strengthening) in every state of Q.  An obligation that
fails in some state of Q is looked for on a real trace from Init (bounded): found, the
invariant is `ill-defined` with that trace; not found, its proof is `unknown`.  A
counterexample trace to an invariant is checked too: a trace that goes through an
ill-defined evaluation is not a counterexample but an `ill-defined` result.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any

import z3

from .obligations import Obligation
from .system import System


@dataclass
class Parts:
    init: list[Obligation]
    trans: list[Obligation]
    predicates: dict[str, list[Obligation]] = field(default_factory=dict)

    def count(self) -> int:
        return len(self.init) + len(self.trans) + sum(len(v) for v in self.predicates.values())


@dataclass
class Undefined:
    obligation: Obligation
    part: str                                   # Init, Next, or the predicate evaluated
    trace: list[dict[str, Any]] | None = None   # a trace from Init to where the site is evaluated
    state: dict[str, Any] | None = None         # else: a state of Q where it fails (maybe unreachable)
    params: dict[str, Any] = field(default_factory=dict)

    def describe(self) -> str:
        o = self.obligation
        return f"{o.where()}: in {self.part}, {o.kind} obligation fails: {o.what}"


def parts_of(sys: System, predicates: dict[str, list[Obligation]]) -> Parts:
    return Parts(sys.init_obligations, sys.trans_obligations, predicates)


def failing_under(sys: System, q: z3.BoolRef, parts: Parts) -> list[Undefined]:
    """The obligations that fail in some state of Q (Init's: under the ASSUMEs only)."""
    out = _failing(sys, [sys.assumptions], parts.init, "Init")
    out += _failing(sys, [sys.assumptions, q], parts.trans, "Next")
    for name, obligations in parts.predicates.items():
        out += _failing(sys, [sys.assumptions, q], obligations, name)
    return out


def _failing(sys: System, context: list[z3.BoolRef], obligations: list[Obligation], part: str) -> list[Undefined]:
    found: list[Undefined] = []
    open_ = list(obligations)
    while open_:
        s = sys.solver(*context, *(o.cond for o in open_))
        s.add(*context)
        s.add(z3.Not(z3.And([o.cond for o in open_])))
        if s.check() != z3.sat:
            break
        m = s.model()
        bad = [o for o in open_ if not z3.is_true(m.eval(o.cond, model_completion=True))]
        if not bad:
            break
        state = sys.state_values(m, None)
        found.extend(Undefined(o, part, state=state, params=sys.param_values(m)) for o in bad)
        open_ = [o for o in open_ if all(o is not b for b in bad)]
    return found


def first_on_trace(sys: System, m: z3.ModelRef, k: int, parts: Parts) -> Undefined | None:
    """The first ill-defined evaluation along the trace of model `m` (steps 0..k of an
    unrolling), in TLC's order: Init, the predicates in state 0, Next from state 0, ..."""
    def fails(f: z3.BoolRef) -> bool:
        return z3.is_false(m.eval(f, model_completion=True))

    def trace(n: int) -> list[dict[str, Any]]:
        return [sys.state_values(m, i) for i in range(n)]
    for o in parts.init:
        if fails(sys.init_at(0, o.cond)):
            return Undefined(o, "Init", trace(1), params=sys.param_values(m))
    for i in range(k + 1):
        for name, obligations in parts.predicates.items():
            for o in obligations:
                if fails(sys.at(o.cond, i)):
                    return Undefined(o, name, trace(i + 1), params=sys.param_values(m))
        if i < k:
            for o in parts.trans:
                if fails(sys.trans_at(i, o.cond)):
                    return Undefined(o, "Next", trace(i + 1), params=sys.param_values(m))
    return None


def reach(sys: System, parts: Parts, depth: int, timeout_s: float) -> Undefined | None:
    """A trace from Init on which some obligation fails, of at most `depth` steps (BMC)."""
    t0 = time.monotonic()
    s = sys.solver()
    s.add(sys.assumptions, sys.init_at(0))
    for k in range(depth + 1):
        if k > 0:
            s.add(sys.trans_at(k - 1))
        here = [sys.at(o.cond, k) for obls in parts.predicates.values() for o in obls]
        here += [sys.trans_at(k, o.cond) for o in parts.trans]
        if k == 0:
            here += [sys.init_at(0, o.cond) for o in parts.init]
        if here:
            s.push()
            s.add(z3.Not(z3.And(here)))
            if s.check() == z3.sat:
                found = first_on_trace(sys, s.model(), k, parts)
                s.pop()
                if found is not None:
                    return found
            else:
                s.pop()
        if time.monotonic() - t0 > timeout_s:
            break
    return None
