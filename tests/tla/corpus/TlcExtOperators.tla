-------------------------- MODULE TlcExtOperators --------------------------
(* The operators of TLCExt whose value TLC defines deterministically:      *)
(* TLCNoOp, TLCCache (the value of its first argument), TLCModelValue (a   *)
(* model value with that name) and AssertEq (a = b, printing both when     *)
(* they differ).  TLC 1.8.0: invariant Small violated at x = 3 (it prints  *)
(* "Assertion failed", FALSE, TRUE), 4 distinct states, 4 generated,       *)
(* depth 4.                                                                 *)
EXTENDS Naturals, TLCExt
VARIABLE x
Init == x = TLCNoOp(0)
Next == x' = TLCCache((x + 1) % 4, {x})
Same == AssertEq(x, x)
Distinct == TLCModelValue("m1") # TLCModelValue("m2")
Small == AssertEq(x < 3, TRUE)
=============================================================================
