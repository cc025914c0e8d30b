--------------------------- MODULE AlternatingBit ---------------------------
(* The alternating bit protocol over lossy FIFO channels, in the style of *)
(* Specifying Systems ch. 14: Lose(q) is called with msgQ and ackQ and    *)
(* assigns q' (TLC substitutes the argument).  Constructs: tuples in      *)
(* sequences, Seq({0,1} \X Data) in TypeOK, CONSTRAINT on queue lengths. *)
(* TLC: success.                                                          *)
EXTENDS Naturals, Sequences
CONSTANTS Data, QLen
VARIABLES msgQ, ackQ, sBit, sAck, rBit, sent, rcvd
Init == /\ msgQ = <<>> /\ ackQ = <<>>
        /\ sBit \in {0, 1} /\ sAck = sBit /\ rBit = sBit
        /\ sent \in Data /\ rcvd \in Data
TypeInv == /\ msgQ \in Seq({0, 1} \X Data) /\ ackQ \in Seq({0, 1})
           /\ sBit \in {0, 1} /\ sAck \in {0, 1} /\ rBit \in {0, 1}
SndNewValue(d) == /\ sAck = sBit
                  /\ sent' = d
                  /\ sBit' = 1 - sBit
                  /\ msgQ' = Append(msgQ, <<sBit', d>>)
                  /\ UNCHANGED <<ackQ, sAck, rBit, rcvd>>
ReSndMsg == /\ sAck # sBit
            /\ msgQ' = Append(msgQ, <<sBit, sent>>)
            /\ UNCHANGED <<ackQ, sBit, sAck, rBit, sent, rcvd>>
RcvMsg == /\ msgQ # <<>>
          /\ msgQ' = Tail(msgQ)
          /\ rBit' = Head(msgQ)[1]
          /\ rcvd' = Head(msgQ)[2]
          /\ UNCHANGED <<ackQ, sBit, sAck, sent>>
SndAck == /\ ackQ' = Append(ackQ, rBit)
          /\ UNCHANGED <<msgQ, sBit, sAck, rBit, sent, rcvd>>
RcvAck == /\ ackQ # <<>>
          /\ ackQ' = Tail(ackQ)
          /\ sAck' = Head(ackQ)
          /\ UNCHANGED <<msgQ, sBit, rBit, sent, rcvd>>
Lose(q) == /\ q # <<>>
           /\ \E i \in 1..Len(q) : q' = [j \in 1..(Len(q) - 1) |-> IF j < i THEN q[j] ELSE q[j + 1]]
           /\ UNCHANGED <<sBit, sAck, rBit, sent, rcvd>>
LoseMsg == Lose(msgQ) /\ UNCHANGED ackQ
LoseAck == Lose(ackQ) /\ UNCHANGED msgQ
Next == \/ \E d \in Data : SndNewValue(d)
        \/ ReSndMsg \/ RcvMsg \/ SndAck \/ RcvAck \/ LoseMsg \/ LoseAck
Spec == Init /\ [][Next]_<<msgQ, ackQ, sBit, sAck, rBit, sent, rcvd>>
QConstraint == Len(msgQ) <= QLen /\ Len(ackQ) <= QLen
Delivered == Len(msgQ) + Len(ackQ) <= 2 * QLen
=============================================================================
