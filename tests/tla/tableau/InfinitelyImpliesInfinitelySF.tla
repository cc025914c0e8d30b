---- MODULE InfinitelyImpliesInfinitelySF ----
(* []<>P => []<>Q holds with strong fairness on Grant. *)
EXTENDS Naturals
VARIABLES req, ack
vars == <<req, ack>>
Init == req = FALSE /\ ack = FALSE
Request == ~req /\ req' = TRUE /\ UNCHANGED ack
Grant == req /\ ~ack /\ ack' = TRUE /\ UNCHANGED req
Deny == req /\ ~ack /\ req' = FALSE /\ UNCHANGED ack
Done == req /\ ack /\ req' = FALSE /\ ack' = FALSE
Next == Request \/ Grant \/ Deny \/ Done
Spec == Init /\ [][Next]_vars /\ WF_vars(Next) /\ SF_vars(Grant)

Prop == []<>req => []<>ack
====
