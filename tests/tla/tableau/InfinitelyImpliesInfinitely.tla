---- MODULE InfinitelyImpliesInfinitely ----
(* []<>P => []<>Q: requests infinitely often imply grants infinitely often, false when Deny is allowed for ever. *)
EXTENDS Naturals
VARIABLES req, ack
vars == <<req, ack>>
Init == req = FALSE /\ ack = FALSE
Request == ~req /\ req' = TRUE /\ UNCHANGED ack
Grant == req /\ ~ack /\ ack' = TRUE /\ UNCHANGED req
Deny == req /\ ~ack /\ req' = FALSE /\ UNCHANGED ack
Done == req /\ ack /\ req' = FALSE /\ ack' = FALSE
Next == Request \/ Grant \/ Deny \/ Done
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)

Prop == []<>req => []<>ack
====
