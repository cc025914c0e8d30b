--------------------------- MODULE AsyncChannel ---------------------------
(* An asynchronous FIFO channel between a sender and a receiver, in the   *)
(* style of Specifying Systems' FIFO: a bounded queue as a sequence.      *)
(* Constructs: Seq(S) membership (infinite set, not enumerated), Append,  *)
(* Head, Tail, Len, SubSeq, \o, SelectSeq.  TLC: success.                 *)
EXTENDS Naturals, Sequences
CONSTANTS Msg, N
VARIABLES q, sent, rcvd
vars == <<q, sent, rcvd>>
Init == q = <<>> /\ sent = <<>> /\ rcvd = <<>>
Send(m) == /\ Len(q) < N
           /\ q' = Append(q, m)
           /\ sent' = IF Len(sent) < 3 THEN sent \o <<m>> ELSE SubSeq(sent, 2, 3) \o <<m>>
           /\ UNCHANGED rcvd
Receive == /\ q # <<>>
           /\ q' = Tail(q)
           /\ rcvd' = SelectSeq(Append(rcvd, Head(q)), LAMBDA m : m # "reset")
           /\ UNCHANGED sent
Reset == /\ Len(rcvd) >= 2
         /\ rcvd' = <<>>
         /\ UNCHANGED <<q, sent>>
Next == (\E m \in Msg : Send(m)) \/ Receive \/ Reset
Spec == Init /\ [][Next]_vars
TypeOK == /\ q \in Seq(Msg)
          /\ sent \in Seq(Msg)
          /\ rcvd \in Seq(Msg)
          /\ Len(q) <= N
Bounded == Len(rcvd) <= N + 1
=============================================================================
