------------------------- MODULE ViolationBeforeError -------------------------
(***************************************************************************)
(* The first successor violates Inv; a later action (A3) would fail to    *)
(* evaluate ((SUBSET 0)..2: SUBSET binds tighter than ..), but TLC stops   *)
(* at the violation and never gets there.  Found by the differential     *)
(* tester (seed 3, spec 992): rebuilding the trace re-ran every action and *)
(* turned the violation into A3's error.                                   *)
(* Expected: safety failure of Inv, 2 generated, 2 distinct, depth 2.     *)
(***************************************************************************)
EXTENDS Naturals, FiniteSets
VARIABLES x
Init == x = 0
A0 == x' = 1
A3 == x' = Cardinality({f \in {1} : \E t \in SUBSET 0..2 : TRUE})
Next == A0 \/ A3
Inv == x = 0
=============================================================================
