--------------------------- MODULE NestedTemporal ---------------------------
(* Nested temporal formulas equal to the checked forms: [](P => <>Q) is    *)
(* P ~> Q, [](P => []Q) says "once P, Q from then on", <>[]<>P is []<>P    *)
(* and []<>[]P is <>[]P; P => <>Q and P => []Q evaluate P on the initial *)
(* state.  A request/acknowledge handshake whose latch,                    *)
(* once set, stays set.  Expected (TLC 1.8.0): success.                    *)
EXTENDS Naturals
VARIABLES req, ack, latched
vars == <<req, ack, latched>>

Init == req = FALSE /\ ack = FALSE /\ latched = FALSE
Request == ~req /\ ~ack /\ req' = TRUE /\ UNCHANGED <<ack, latched>>
Acknowledge == req /\ ~ack /\ ack' = TRUE /\ latched' = TRUE /\ UNCHANGED req
Reset == req /\ ack /\ req' = FALSE /\ ack' = FALSE /\ UNCHANGED latched
Next == Request \/ Acknowledge \/ Reset
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)

ReqLeadsToAck == [](req => <>ack)
LatchStays == [](latched => []latched)
AckInfinitelyOften == <>[]<>ack
LatchedForGood == []<>[]latched
IdleThenAck == ~req => <>ack
IdleThenSafe == ~req => [](ack => latched)
=============================================================================
