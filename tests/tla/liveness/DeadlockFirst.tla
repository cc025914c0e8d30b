--------------------------- MODULE DeadlockFirst ---------------------------
(* A counter that stops at 2, checked with deadlock detection on and a    *)
(* liveness property: TLC reports the deadlock (a safety error, exit 11)  *)
(* before it checks any temporal property.                                *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Inc == x < 2 /\ x' = x + 1
Spec == Init /\ [][Inc]_x /\ WF_x(Inc)
Reaches == <>(x = 2)
=============================================================================
