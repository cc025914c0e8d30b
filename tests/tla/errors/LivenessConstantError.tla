------------------------ MODULE LivenessConstantError ------------------------
(* A part of a liveness property that reads no variable is evaluated when  *)
(* TLC builds the property's tableau, before the search: here SUBSET 0..2  *)
(* is (SUBSET 0)..2, an error, so TLC stops with exit code 255 before it   *)
(* could find that Small is violated.  Found by the differential tester.   *)
EXTENDS Naturals
VARIABLE x

Init == x = 0
Next == x' = (x + 1) % 3
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Small == x < 2
Prop == (\E t \in SUBSET 0..2 : t = {}) ~> (x = 2)
=============================================================================
