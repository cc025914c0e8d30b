---- MODULE LeadsToStableFails ----
(* [](P => <>[]Q) violated: the wrapping counter leaves 3 again. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == [](x = 1 => <>[](x = 3))
====
