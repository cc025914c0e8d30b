---------------------------- MODULE EnumerateNat ----------------------------
(* Init picks x from Nat, which TLC cannot enumerate.                     *)
(* Expected: evaluation error at line 6, column 9 (exit 75).             *)
EXTENDS Naturals
VARIABLE x
Init == x \in Nat
Next == x' = x + 1
=============================================================================
