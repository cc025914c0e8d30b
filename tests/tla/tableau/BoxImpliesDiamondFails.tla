---- MODULE BoxImpliesDiamondFails ----
(* []P => <>Q without fairness: stuttering at 0 violates it. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x

Prop == [](x <= 3) => <>(x = 3)
====
