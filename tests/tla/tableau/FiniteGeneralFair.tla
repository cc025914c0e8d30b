---- MODULE FiniteGeneralFair ----
(* The same with weak fairness: TLC checks it on cycles after the search (exit 13). *)
EXTENDS Naturals
VARIABLES x, y
vars == <<x, y>>
Init == x = 0 /\ y \in {0, 1}
Next == x' = (x + 1) % 4 /\ y' = 1 - y
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)

Prop == [](x < 2 \/ [](x = 3)) \/ <>(x = 1 /\ y = 1 /\ x = 0)
====
