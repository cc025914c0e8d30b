"""Vacuity of a proof: a proved invariant that holds only because nothing it talks about
can happen.  Two checks, with the solver:

* Init is satisfiable under the ASSUMEs together with Q (the invariant, TypeOK's domains
  and the strengthening invariants): no initial state means every invariant "holds";
* for each conjunct of the invariant written ``A => B``, A is satisfiable together with Q:
  an antecedent no state of Q satisfies makes the conjunct true for nothing.
"""

from __future__ import annotations

import z3

from .system import System


def vacuity(sys: System, name: str, q: z3.BoolRef) -> list[str]:
    """Why the proof of `name` is vacuous (empty: it is not)."""
    problems = []
    if _unsat(sys, sys.assumptions, sys.init_at(0)):
        problems.append("Init has no state satisfying the ASSUMEs")
    elif _unsat(sys, sys.assumptions, sys.init_at(0), sys.at(q, 0)):
        problems.append("no initial state satisfies the strengthened invariant")
    for where, antecedent in sys.implications(name):
        if _unsat(sys, sys.assumptions, q, antecedent):
            problems.append(f"the antecedent at {where} holds in no state of the invariant")
    return problems


def _unsat(sys: System, *formulas: z3.BoolRef) -> bool:
    s = sys.solver(*formulas)
    s.add(*formulas)
    return s.check() == z3.unsat
