---------------------------- MODULE SortedInsert ----------------------------
(* An insertion-sorted list with the order given as an operator constant *)
(* of two arguments, substituted in the .cfg (Leq <- ByLength); the      *)
(* invariant uses SortSeq with the same operator and a LAMBDA.            *)
(* TLC: success.                                                          *)
EXTENDS Naturals, Sequences, TLC
CONSTANTS Leq(_, _), Words
VARIABLES list, pool
ByLength(a, b) == Len(a) <= Len(b)
Insert(s, w) == LET pos == CHOOSE i \in 1..(Len(s) + 1) :
                             /\ \A j \in 1..(i - 1) : Leq(s[j], w)
                             /\ \A j \in i..Len(s) : ~Leq(s[j], w)
                IN SubSeq(s, 1, pos - 1) \o <<w>> \o SubSeq(s, pos, Len(s))
Init == list = <<>> /\ pool = Words
Next == \E w \in pool : /\ list' = Insert(list, w)
                        /\ pool' = pool \ {w}
Sorted == \A i \in 1..(Len(list) - 1) : Leq(list[i], list[i + 1])
SameAsSortSeq == Len(SortSeq(list, LAMBDA a, b : Len(a) < Len(b))) = Len(list)
=============================================================================
