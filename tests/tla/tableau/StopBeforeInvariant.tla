---- MODULE StopBeforeInvariant ----
(* No fairness, an invariant and a property with a finite counterexample: expanding x = 3 completes the counterexample of Prop (x = 1 then x = 3) before the expansion of x = 4 meets the invariant violation x = 5: TLC reports the property *)
EXTENDS Naturals
VARIABLES x
Init == x = 0
Next == x < 6 /\ x' = x + 1
Spec == Init /\ [][Next]_x
Small == x < 5
Prop == [](x = 1 => [](x # 3)) \/ x = 5
====
