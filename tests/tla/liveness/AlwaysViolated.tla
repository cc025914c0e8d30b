--------------------------- MODULE AlwaysViolated ---------------------------
(* A state property []P given under PROPERTY (not INVARIANT): TLC checks *)
(* it on every state as an implied invariant.  x reaches 3, violating     *)
(* [](x < 3).                                                             *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 5
Spec == Init /\ [][Next]_x /\ WF_x(Next)
Small == [](x < 3)
=============================================================================
