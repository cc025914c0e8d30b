---------------------------- MODULE Handshake ----------------------------
(* Alternating-bit style handshake between a sender and a receiver, with *)
(* weak fairness on both.  Properties: every message sent is acked       *)
(* (~>), acks keep coming ([]<>), the bits never run ahead by more than  *)
(* one ([] of a state predicate in PROPERTY) and every step flips exactly *)
(* one bit ([][A]_v).  Expected: success.                                 *)
EXTENDS Integers
VARIABLES sbit, rbit
vars == <<sbit, rbit>>
Init == sbit = 0 /\ rbit = 0
Send == sbit = rbit /\ sbit' = 1 - sbit /\ UNCHANGED rbit
Ack == sbit /= rbit /\ rbit' = sbit /\ UNCHANGED sbit
Next == Send \/ Ack
Spec == Init /\ [][Next]_vars /\ WF_vars(Send) /\ WF_vars(Ack)

Acked == (sbit /= rbit) ~> (sbit = rbit)
AcksForever == []<>(sbit = rbit)
InStep == [](sbit - rbit \in {-1, 0, 1})
OneBit == [][(sbit' = sbit) # (rbit' = rbit)]_vars
=============================================================================
