---- MODULE StrongFairnessImpliesFails ----
(* SF_x(Next) => <>(x = 2) /\ [](x = 2 => <>(x = 0)): the counter stops at 3. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x

Prop == SF_x(Next) => (<>(x = 2) /\ [](x = 2 => <>(x = 0)))
====
