---- MODULE StableOrInfinitelyStutters ----
(* <>[]P \/ []<>Q without fairness: stuttering at 0 violates it. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x

Prop == <>[](x = 1) \/ []<>(x = 1 /\ x = 0)
====
