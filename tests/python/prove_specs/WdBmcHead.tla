----------------------------- MODULE WdBmcHead -----------------------------
(* Head(q) in Next without looking: the first step empties q, the second   *)
(* takes the Head of << >> (TLC stops with an evaluation error there).     *)
EXTENDS Naturals, Sequences
VARIABLE q, h

Init == q = <<1>> /\ h = 0
Next == h' = Head(q) /\ q' = Tail(q)

TypeOK == q \in Seq({1}) /\ Len(q) <= 1 /\ h \in 0..1
HeadBit == h \in 0..1
=============================================================================
