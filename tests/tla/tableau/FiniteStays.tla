---- MODULE FiniteStays ----
(* [](P => []Q) without fairness: TLC stops its search at the first finite counterexample (exit 12). *)
EXTENDS Naturals
VARIABLES x, y
vars == <<x, y>>
Init == x = 0 /\ y \in {0, 1}
Next == x' = (x + 1) % 4 /\ y' = 1 - y
Spec == Init /\ [][Next]_vars

Prop == [](x = 1 => [](x # 3))
====
