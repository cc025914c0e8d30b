---- MODULE EmptySeqBranch ----
\* An IF whose branches are an empty sequence literal and a one-element one:
\* the prover gives <<>> the shape of the other branch (a sequence of
\* symbolic length), so ShortOut is proved and OneOut is refuted at x = 0.
EXTENDS Naturals, Sequences
VARIABLE x
TypeOK == x \in 0..3
Init == x = 0
Next == x' = (x + 1) % 4
Out == IF x = 0 THEN <<>> ELSE <<x>>
ShortOut == Len(Out) <= 1
OneOut == Len(Out) = 1
====
