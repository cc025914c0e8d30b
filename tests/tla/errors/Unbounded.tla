----------------------------- MODULE Unbounded -----------------------------
(* The next-state relation chooses the new value from Nat, an infinite     *)
(* set that TLC cannot enumerate.  Expected: evaluation error at line 10.  *)
EXTENDS Naturals

VARIABLE x

Init == x = 0

Next == \E n \in Nat : /\ n > x
                       /\ x' = n
=============================================================================
