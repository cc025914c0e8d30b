---- MODULE LeadsToStableHolds ----
(* [](P => <>[]Q): once x = 3 the counter stays there (WF). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == [](x = 1 => <>[](x = 3))
====
