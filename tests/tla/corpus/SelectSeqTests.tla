---- MODULE SelectSeqTests ----
\* SelectSeq in actions with each kind of test: a user operator, a LET operator (whose
\* body reads a variable) and a LAMBDA.
EXTENDS Naturals, Sequences
VARIABLES q, kept
Small(x) == x < 3
Init == q = <<>> /\ kept = <<>>
Next == \/ Len(q) < 3 /\ \E x \in 1..3 : q' = Append(q, x) /\ UNCHANGED kept
        \/ LET Kept(x) == x % 2 = Len(kept) % 2 IN kept' = SelectSeq(q, Kept) /\ q' = SelectSeq(q, Small)
        \/ kept' = SelectSeq(q, LAMBDA x : x > Len(kept)) /\ UNCHANGED q
Inv == Len(kept) <= 3
====
