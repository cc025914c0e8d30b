---- MODULE StableOrInfinitelyFails ----
(* <>[]P \/ []<>Q violated by the fair toggle (neither holds). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == <>[](x = 0) \/ []<>(x = 2)
====
