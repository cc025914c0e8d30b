------------------------------ MODULE WdTail ------------------------------
(* A queue that is taken from without looking: Tail of << >> in Next.      *)
EXTENDS Naturals, Sequences
VARIABLE q

Init == q = <<>>
Next == \/ Len(q) < 2 /\ q' = Append(q, 1)
        \/ q' = Tail(q)

TypeOK == q \in Seq({1}) /\ Len(q) <= 2
=============================================================================
