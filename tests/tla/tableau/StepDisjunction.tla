---- MODULE StepDisjunction ----
(* A disjunction with a step formula: []<>(x = 3) \/ []<><<Next>>_x holds: the counter stops at 3. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == []<>(x = 3) \/ []<><<Next>>_x
====
