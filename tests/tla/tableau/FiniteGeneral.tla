---- MODULE FiniteGeneral ----
(* A general property violated by a finite prefix (every continuation fails), no fairness: TLC stops early. *)
EXTENDS Naturals
VARIABLES x, y
vars == <<x, y>>
Init == x = 0 /\ y \in {0, 1}
Next == x' = (x + 1) % 4 /\ y' = 1 - y
Spec == Init /\ [][Next]_vars

Prop == [](x < 2 \/ [](x = 3)) \/ <>(x = 1 /\ y = 1 /\ x = 0)
====
