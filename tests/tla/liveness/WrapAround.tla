---------------------------- MODULE WrapAround ----------------------------
(* A counter modulo 4: the action property "x never decreases" is violated *)
(* by the step 3 -> 0, reported as TLC's action property violation.        *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Increasing == [][x' > x]_x
=============================================================================
