---- MODULE ExistsStable ----
(* \E v \in S : <>[](x = v) holds on the terminating counter (WF). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == \E v \in 0..3 : <>[](x = v)
====
