---------------------------- MODULE WdUndefined ----------------------------
(* Invariants whose evaluation TLA+ leaves undefined in a reachable state   *)
(* (TLC stops with an error there): each is ill-defined, not proved.        *)
EXTENDS Naturals, Sequences
VARIABLE x, r, q

f == [i \in 0..1 |-> 2 * i]

Init == x = 0 /\ r = [a |-> 1] /\ q = <<5>>
Next == x' = (x + 1) % 3 /\ UNCHANGED <<r, q>>

TypeOK == x \in 0..2 /\ r \in [a : 0..3] /\ q \in Seq(0..9) /\ Len(q) <= 2
OutsideDomain == f[x] >= 0                  \* x = 2 is outside DOMAIN f
MissingField == x = 2 => r.b = 1            \* r has no field b
SubSeqOutOfRange == x = 1 => SubSeq(q, 1, 2) = <<5, 5>>   \* Len(q) = 1
HeadOfEmpty == x = 2 => Head(Tail(q)) = 5   \* Tail(q) = << >>
=============================================================================
