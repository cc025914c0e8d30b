---- MODULE StableOrInfinitelyHolds ----
(* A disjunction <>[]P \/ []<>Q: under WF the toggle visits 0 forever. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == <>[](x = 1) \/ []<>(x = 0)
====
