---- MODULE EventuallyOnlyStuttersFails ----
(* <>[][x' = x]_x violated by the fair toggle. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == <>[][x' = x]_x
====
