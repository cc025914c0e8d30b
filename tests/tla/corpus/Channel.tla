------------------------------ MODULE Channel ------------------------------
(***************************************************************************)
(* A bounded FIFO channel of capacity Cap carrying values from Msg, kept   *)
(* as a sequence in q.  No .cfg: BoundedFifo instantiates it, substituting *)
(* all three parameters.                                                   *)
(***************************************************************************)
EXTENDS Naturals, Sequences

CONSTANTS Msg, Cap
VARIABLE q

ChanTypeOK == q \in Seq(Msg) /\ Len(q) <= Cap

ChanInit == q = << >>

CanSend == Len(q) < Cap
Send(m) == CanSend /\ q' = Append(q, m)

CanRecv == q /= << >>
Recv == CanRecv /\ q' = Tail(q)
=============================================================================
