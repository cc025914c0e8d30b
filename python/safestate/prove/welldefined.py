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

from .engines.result import Result
from .obligations import Obligation, conjunction
from .system import System


@dataclass
class Parts:
    init: list[Obligation]
    trans: list[Obligation]
    predicates: dict[str, list[Obligation]] = field(default_factory=dict)

    def count(self) -> int:
        """How many obligations: Init's, and the distinct sites of Next and the predicates."""
        rest = [*self.trans, *(o for v in self.predicates.values() for o in v)]
        return len(self.init) + len({o.cond.get_id() for o in rest})


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
    """The obligations that fail in some state of Q (Init's: under the ASSUMEs only).

    One solver context for all of them: the ASSUMEs asserted once, Init's obligations
    checked first, then Q added and Next's and every predicate's checked together; a
    site shared by several parts (an operator used by Next and by two invariants) is one
    obligation, checked once, and reported for the first part that has it."""
    everything = [o.cond for o in parts.init] + [o.cond for o in parts.trans] + \
        [o.cond for obligations in parts.predicates.values() for o in obligations]
    s = sys.solver(q, *everything)
    s.add(sys.assumptions)
    out = _failing(sys, s, [(o, "Init") for o in parts.init])
    s.add(q)
    tagged = [(o, "Next") for o in parts.trans]
    tagged += [(o, name) for name, obligations in parts.predicates.items() for o in obligations]
    return out + _failing(sys, s, _one_per_site(tagged))


def _one_per_site(tagged: list[tuple[Obligation, str]]) -> list[tuple[Obligation, str]]:
    seen: set[int] = set()
    out = []
    for o, part in tagged:
        key = o.cond.get_id()
        if key not in seen:
            seen.add(key)
            out.append((o, part))
    return out


def _failing(sys: System, s: z3.Solver, tagged: list[tuple[Obligation, str]]) -> list[Undefined]:
    """The obligations of `tagged` some model of the solver's context violates: one query
    for all of them (unsat: all hold), and one more per batch of violated ones found."""
    found: list[Undefined] = []
    open_ = list(tagged)
    while open_:
        s.push()
        s.add(z3.Not(conjunction([o.cond for o, _ in open_])))
        r = s.check()
        m = s.model() if r == z3.sat else None
        s.pop()
        if r == z3.unknown:  # not proved: every open obligation counts as failing (no state to show)
            found.extend(Undefined(o, part) for o, part in open_)
            break
        if m is None:
            break
        bad = [(o, part) for o, part in open_ if not z3.is_true(m.eval(o.cond, model_completion=True))]
        if not bad:
            break
        state, params = sys.state_values(m, None), sys.param_values(m)
        found.extend(Undefined(o, part, state=state, params=params) for o, part in bad)
        open_ = [t for t in open_ if all(t[0] is not b for b, _ in bad)]
    return found


def first_on_trace(sys: System, m: z3.ModelRef, k: int, parts: Parts, last_step: bool = False) -> Undefined | None:
    """The first ill-defined evaluation along the trace of model `m` (steps 0..k of an
    unrolling), in TLC's order: Init, the predicates in state 0, Next from state 0, ...
    With `last_step`, also Next out of state k (reach() asks for such a step without
    adding it: a step the translation cannot represent, e.g. a value outside TypeOK's
    domain, would be excluded by it); a counterexample ending in state k stops there."""
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
        if i < k or last_step:
            for o in parts.trans:
                if fails(sys.trans_at(i, o.cond)):
                    return Undefined(o, "Next", trace(i + 1), params=sys.param_values(m))
    return None


def undefined_at(sys: System, s: z3.Solver, parts: Parts, k: int) -> Undefined | None:
    """On the unrolling of the solver's context (Init and k steps of Next): an evaluation
    at step k that TLA+ leaves undefined -- Init's (k = 0), the predicates' in state k, or
    Next's out of state k (a step asked for, not added: a step the translation cannot
    represent, e.g. a value outside TypeOK's domain, would be excluded by it)."""
    here: list[z3.BoolRef] = []  # one substitution per part, not per obligation (the press has ~10^5)
    predicates = [o.cond for obls in parts.predicates.values() for o in obls]
    if predicates:
        here.append(sys.at(conjunction(predicates), k))
    if parts.trans:
        here.append(sys.trans_at(k, conjunction([o.cond for o in parts.trans])))
    if k == 0 and parts.init:
        here.append(sys.init_at(0, conjunction([o.cond for o in parts.init])))
    if not here:
        return None
    s.push()
    s.add(z3.Not(z3.And(here)))
    found = first_on_trace(sys, s.model(), k, parts, last_step=True) if s.check() == z3.sat else None
    s.pop()
    return found


def reach(sys: System, parts: Parts, depth: int, timeout_s: float) -> Undefined | None:
    """A trace from Init on which some obligation fails, of at most `depth` steps (BMC)."""
    t0 = time.monotonic()
    s = sys.solver()
    s.add(sys.assumptions, sys.init_at(0))
    for k in range(depth + 1):
        if k > 0:
            s.add(sys.trans_at(k - 1))
        found = undefined_at(sys, s, parts, k)
        if found is not None:
            return found
        if time.monotonic() - t0 > timeout_s:
            break
    return None


def mark_undefined(sys: System, res: Result, u: Undefined, how: str) -> None:
    """`res` meets the failing obligation `u` on a trace from Init.  A 'type' obligation
    is a step out of the type invariant's domain (which the translation cannot
    represent): a violation of the type invariant itself, and for any other property
    the end of what the proof can follow."""
    res.undefined, res.trace, res.params = u.describe(), u.trace, u.params
    step = "" if not u.trace else f"on the step out of state {len(u.trace)} " if u.part == "Next" else \
        f"in state {len(u.trace)} "  # numbered from 1, as the trace is printed
    if u.obligation.kind != "type":
        res.status = "ill-defined"
        res.note = f"{how} an evaluation TLA+ leaves undefined {step}(TLC stops with an error there)"
    elif res.invariant == sys.tr.type_invariant:
        res.status = "violated"
        res.note = (f"the next step leaves {res.invariant}'s domain ({u.describe()}); the state after it "
                    f"is outside what the translation represents and is not shown")
    else:
        res.status = "unknown"
        res.note = (f"{how} a step out of {sys.tr.type_invariant}'s domain {step}({u.describe()}); "
                    f"{sys.tr.type_invariant} is violated there, and the proof cannot follow the spec further")
