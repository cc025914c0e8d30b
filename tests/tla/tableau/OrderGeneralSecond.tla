---- MODULE OrderGeneralSecond ----
(* Two violated general properties, no fairness: TLC checks them in .cfg order (Reaches first). NoTableau's
   negation has no tableau part and only the loop 0, 1 violates it (it violates Reaches too); Reaches
   alone is violated by stuttering at 0. *)
EXTENDS Naturals
VARIABLES x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x
NoTableau == <>[](x # 1) \/ []<>(x = 2)
Reaches == <>(x = 2) \/ <>[](x = 1)
====
