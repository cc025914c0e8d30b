---- MODULE EventuallyOnlyStutters ----
(* <>[][x' = x]_x: the counter stops, so eventually every step leaves x alone. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == <>[][x' = x]_x
====
