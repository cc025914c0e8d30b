------------------------ MODULE NestedTemporalFails ------------------------
(* As NestedTemporal, but Reset clears the latch: [](latched => []latched) *)
(* is violated (the latch is set, then cleared), while [](req => <>ack)    *)
(* still holds.  Expected (TLC 1.8.0): temporal property LatchStays        *)
(* violated, exit 13.                                                      *)
EXTENDS Naturals
VARIABLES req, ack, latched
vars == <<req, ack, latched>>

Init == req = FALSE /\ ack = FALSE /\ latched = FALSE
Request == ~req /\ ~ack /\ req' = TRUE /\ UNCHANGED <<ack, latched>>
Acknowledge == req /\ ~ack /\ ack' = TRUE /\ latched' = TRUE /\ UNCHANGED req
Reset == req /\ ack /\ req' = FALSE /\ ack' = FALSE /\ latched' = FALSE
Next == Request \/ Acknowledge \/ Reset
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)

ReqLeadsToAck == [](req => <>ack)
LatchStays == [](latched => []latched)
=============================================================================
