"""`safestate prove`: unbounded, parametric proofs of TLA+ invariants with z3.

The model is translated to a symbolic transition system (system.py, using the
checker's front end), then each invariant is proved by k-induction, PDR
(Spacer) or refuted by bounded model checking (engines/).  See docs/prove.md.
"""
