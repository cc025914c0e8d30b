"""Vacuity of a proof: a proved invariant that holds only because nothing it talks about
can happen.  Two checks, with the solver:

* Init is satisfiable under the ASSUMEs together with Q (the invariant, TypeOK's domains
  and the strengthening invariants): no initial state means every invariant "holds";
* for each conjunct of the invariant written ``A => B``, A is satisfiable together with Q:
  an antecedent no state of Q satisfies makes the conjunct true for nothing.

The invariants of one joint proof share Q: one solver context (the ASSUMEs and Q
asserted once), one query per distinct antecedent.
"""

from __future__ import annotations

import z3

from .system import System


def vacuity(sys: System, name: str, q: z3.BoolRef) -> list[str]:
    """Why the proof of `name` is vacuous (empty: it is not)."""
    return vacuity_of_group(sys, [name], q)[name]


def vacuity_of_group(sys: System, names: list[str], q: z3.BoolRef) -> dict[str, list[str]]:
    """Why the proof of each of `names`, all under the same Q, is vacuous."""
    antecedents = {name: sys.implications(name) for name in names}
    s = sys.solver(q, *(a for pairs in antecedents.values() for _, a in pairs))
    s.add(sys.assumptions)
    common = []
    if not _sat_with(s, sys.init_at(0)):
        common.append("Init has no state satisfying the ASSUMEs")
    elif not _sat_with(s, sys.init_at(0), sys.at(q, 0)):
        common.append("no initial state satisfies the strengthened invariant")
    s.add(q)
    reachable: dict[int, bool] = {}  # an antecedent shared by several invariants: one query
    out = {}
    for name, pairs in antecedents.items():
        problems = list(common)
        for where, antecedent in pairs:
            key = antecedent.get_id()
            if key not in reachable:
                reachable[key] = _sat_with(s, antecedent)
            if not reachable[key]:
                problems.append(f"the antecedent at {where} holds in no state of the invariant")
        out[name] = problems
    return out


def _sat_with(s: z3.Solver, *formulas: z3.BoolRef) -> bool:
    """Is the solver's context satisfiable together with `formulas` (unknown counts as yes:
    vacuity is a warning, not a proof)."""
    s.push()
    s.add(*formulas)
    r = s.check()
    s.pop()
    return r != z3.unsat
