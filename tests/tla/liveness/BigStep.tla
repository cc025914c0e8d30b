------------------------------ MODULE BigStep ------------------------------
(* A counter that moves by 1 or 3; the action property allows steps of 3  *)
(* only below 4.  The violating step 4 -> 7 reaches a new state, which    *)
(* TLC counts as distinct but never queues (2 states left on queue).      *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 20 /\ (x' = x + 1 \/ x' = x + 3)
Spec == Init /\ [][Next]_x
SmallSteps == [][x' = x + 1 \/ x < 4]_x
=============================================================================
