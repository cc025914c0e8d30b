---------------------------- MODULE ProdConsSF ----------------------------
(* A producer and a consumer share a buffer of size 2.  A "flush" switch  *)
(* toggles; the consumer may only take while the switch is on, so Get is *)
(* enabled only intermittently.  Strong fairness on Get guarantees every *)
(* produced item is eventually consumed.  Expected: success.             *)
EXTENDS Naturals
CONSTANT Cap
VARIABLES buf, open
vars == <<buf, open>>
Init == buf = 0 /\ open = FALSE
Put == buf < Cap /\ buf' = buf + 1 /\ UNCHANGED open
Get == open /\ buf > 0 /\ buf' = buf - 1 /\ UNCHANGED open
Toggle == open' = ~open /\ UNCHANGED buf
Next == Put \/ Get \/ Toggle
Spec == Init /\ [][Next]_vars /\ WF_vars(Toggle) /\ SF_vars(Get)

Drains == (buf = Cap) ~> (buf < Cap)
=============================================================================
