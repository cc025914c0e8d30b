----------------------------- MODULE Unbounded -----------------------------
EXTENDS Naturals, Sequences
VARIABLE q
Init == q = << >>
Next == q' = Append(q, 1)
\* No Len(q) <= N conjunct: the prover cannot size the sequence.
TypeOK ==
       q \in Seq(Nat)
Short == Len(q) < 3
=============================================================================
