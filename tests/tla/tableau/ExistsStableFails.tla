---- MODULE ExistsStableFails ----
(* \E v \in S : <>[](x = v) violated by the wrapping counter (WF). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == \E v \in 0..3 : <>[](x = v)
====
