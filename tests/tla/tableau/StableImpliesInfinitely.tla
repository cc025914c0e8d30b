---- MODULE StableImpliesInfinitely ----
(* <>[]P => []<>Q under fairness and a conjunction with a fixed form. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == (<>[](x = 0) => []<>(x = 1)) /\ []<>(x = 1)
====
