"""PDR/IC3 with z3's Horn-clause engine Spacer.

The reachable states are the least relation Reach(c, s) (c: the symbolic
constants) with
    Assume(c) /\\ Init(s)               => Reach(c, s)
    Reach(c, s) /\\ Next(s, s')          => Reach(c, s')
and P is proved when  Reach(c, s) /\\ ~P(s) => false  is satisfiable (Spacer
finds an inductive invariant).  A reachable violation is then replayed by BMC
for its trace.
"""

from __future__ import annotations

import time
from typing import Callable

import z3

from ..system import System
from .result import Result


def pdr(sys: System, name: str, prop: z3.BoolRef, timeout_s: float,
        log: Callable[[str], None] = lambda s: None) -> Result:
    t0 = time.monotonic()
    ufs = [n for n, v in sys.params.items() if getattr(v, "extra", {}).get("uf") is not None]
    if ufs:
        return Result(name, "unknown", "pdr", None, 0.0,
                      note=f"Spacer takes no uninterpreted functions: {', '.join(ufs)} (any subset of an "
                           f"infinite set) cannot stay symbolic; use --cfg-constants or the kind engine")
    fp = z3.Fixedpoint()
    fp.set(engine="spacer")
    fp.set("timeout", int(timeout_s * 1000))
    cur = sys.param_leaves + sys.cur_leaves
    nxt = sys.param_leaves + sys.nxt_leaves
    reach = z3.Function("Reach", *[x.sort() for x in cur], z3.BoolSort())
    fp.register_relation(reach)
    fp.declare_var(*(cur + sys.nxt_leaves + sys.init_aux + sys.trans_aux))
    fp.rule(reach(*cur), z3.And(sys.assumptions, sys.init))
    fp.rule(reach(*nxt), z3.And(reach(*cur), sys.trans))
    try:
        r = fp.query(z3.And(reach(*cur), z3.Not(prop)))
    except z3.Z3Exception as e:
        return Result(name, "unknown", "pdr", None, time.monotonic() - t0, note=f"Spacer failed: {e}")
    secs = time.monotonic() - t0
    log(f"pdr {name}: {r} ({secs:.1f}s)")
    if r == z3.unsat:
        inv = fp.get_answer()
        res = Result(name, "proved", "pdr", None, secs)
        text = " ".join(str(inv).split())
        res.note = (f"inductive invariant found by Spacer: {text}" if len(text) <= 300 else
                    f"inductive invariant found by Spacer ({len(text)} characters)")
        return res
    if r == z3.sat:
        return Result(name, "violated", "pdr", None, secs, note="Spacer found a reachable violation")
    return Result(name, "unknown", "pdr", None, secs, note=f"Spacer: {fp.reason_unknown()}")
