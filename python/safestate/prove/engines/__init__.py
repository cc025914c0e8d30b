"""Proof engines: bounded model checking, k-induction, PDR (Spacer)."""
