---- MODULE EmptySeqBranch ----
\* An IF whose branches are an empty sequence literal and a one-element one:
\* the prover cannot give <<>> a shape, and must say where (file:line:col).
EXTENDS Naturals, Sequences
VARIABLE x
TypeOK == x \in 0..3
Init == x = 0
Next == x' = (x + 1) % 4
Out == IF x = 0 THEN <<>> ELSE <<x>>
ShortOut == Len(Out) <= 1
====
