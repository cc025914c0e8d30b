------------------------- MODULE NestedTemporalInit -------------------------
(* P => []Q with P true on the initial state, in the form published specs  *)
(* use for "if every process starts idle, none ever commits": here the     *)
(* handshake starts idle and later acknowledges, so IdleThenNoAck fails.   *)
(* Expected (TLC 1.8.0): temporal property IdleThenNoAck violated, exit 13.*)
EXTENDS Naturals
VARIABLES req, ack
vars == <<req, ack>>

Init == req = FALSE /\ ack = FALSE
Request == ~req /\ ~ack /\ req' = TRUE /\ UNCHANGED ack
Acknowledge == req /\ ~ack /\ ack' = TRUE /\ UNCHANGED req
Reset == req /\ ack /\ req' = FALSE /\ ack' = FALSE
Next == Request \/ Acknowledge \/ Reset
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)

IdleThenNoAck == ~req => [](~ack)
=============================================================================
