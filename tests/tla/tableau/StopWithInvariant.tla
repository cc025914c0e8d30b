---- MODULE StopWithInvariant ----
(* No fairness, an invariant and a property with a finite counterexample: the invariant violation x = 4 and the counterexample of Prop are both met while expanding x = 3: TLC reports the invariant first *)
EXTENDS Naturals
VARIABLES x
Init == x = 0
Next == x < 6 /\ x' = x + 1
Spec == Init /\ [][Next]_x
Small == x < 4
Prop == [](x = 1 => [](x # 3)) \/ x = 5
====
