---------------------------- MODULE CountToFive ----------------------------
(* A counter with weak fairness that stops at 3.  Its only behaviours end *)
(* by stuttering at 3, so <>(x = 5) fails only through stuttering, even   *)
(* though every step is fair.  Deadlock checking is off.                  *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Inc == x < 3 /\ x' = x + 1
Spec == Init /\ [][Inc]_x /\ WF_x(Inc)

ReachesFive == <>(x = 5)
ReachesThree == <>(x = 3)
StaysAtThree == <>[](x = 3)
=============================================================================
