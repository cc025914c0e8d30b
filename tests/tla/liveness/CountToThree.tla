---------------------------- MODULE CountToThree ----------------------------
(* The counter of CountToFive: with WF it reaches 3 and stays there.       *)
(* Expected: success (deadlock checking off).                              *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Inc == x < 3 /\ x' = x + 1
Spec == Init /\ [][Inc]_x /\ WF_x(Inc)

ReachesThree == <>(x = 3)
StaysAtThree == <>[](x = 3)
Monotone == [][x' >= x]_x
=============================================================================
