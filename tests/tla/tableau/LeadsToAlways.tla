---- MODULE LeadsToAlways ----
(* P ~> []Q: after a request the grant/deny cycle need not stay granted. *)
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

Prop == req ~> []ack
====
