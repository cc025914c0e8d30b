--------------------------- MODULE WdStrengthen ----------------------------
(* A strengthening invariant that excludes the initial state (x > 0 with   *)
(* x = 0 initially): the proof must fail on it, never prove vacuously.      *)
EXTENDS Naturals
VARIABLE x

Init == x = 0
Next == x' = x

TypeOK == x \in Nat
NonNegative == x >= 0
Wrong == x > 0
=============================================================================
