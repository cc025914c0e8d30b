---- MODULE FairnessImplies ----
(* WF_x(Next) => <>(x = 3) holds without fairness in the spec. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x

Prop == WF_x(Next) => <>(x = 3)
====
