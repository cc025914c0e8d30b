---------------------------- MODULE ProdConsWF ----------------------------
(* A producer and a consumer share a buffer of size 2.  A "flush" switch  *)
(* toggles; the consumer may only take while the switch is on, so Get is *)
(* enabled only intermittently.  Weak fairness on Get is not enough: a   *)
(* full buffer may stay full forever.  Expected: violation.              *)
EXTENDS Naturals
CONSTANT Cap
VARIABLES buf, open
vars == <<buf, open>>
Init == buf = 0 /\ open = FALSE
Put == buf < Cap /\ buf' = buf + 1 /\ UNCHANGED open
Get == open /\ buf > 0 /\ buf' = buf - 1 /\ UNCHANGED open
Toggle == open' = ~open /\ UNCHANGED buf
Next == Put \/ Get \/ Toggle
Spec == Init /\ [][Next]_vars /\ WF_vars(Toggle) /\ WF_vars(Get)

Drains == (buf = Cap) ~> (buf < Cap)
=============================================================================
