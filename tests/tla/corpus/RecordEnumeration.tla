---- MODULE RecordEnumeration ----
\* Actions that enumerate sets of records [f : S] whose fields are not in alphabetical
\* order: the checker enumerates such a set as the product of its fields' sets (the
\* last field turning fastest), a filter of one as a plain set.  The order decides the
\* order in which states are found (their numbers in the state graph); it is not TLC's
\* order of the records ("alpha" comes first in the module: its rank is lower).
EXTENDS Naturals
VARIABLES msg, last, n
Init == msg = [alpha |-> "", mid |-> FALSE, zeta |-> 0] /\ last = 0 /\ n = 0
Msgs == [zeta : {1, 2}, alpha : {"b", "a"}, mid : BOOLEAN]
Receive(m) == msg' = m /\ last' = m.zeta /\ n' = (n + 1) % 3
Next == \/ \E m \in Msgs : Receive(m)
        \/ \E m \in {r \in Msgs : r.mid} : msg' = m /\ last' = 4 /\ UNCHANGED n
        \/ LET Late == [zeta : {5, 4}, alpha : {"z"}] IN \E m, k \in Late : msg' = m /\ last' = k.zeta /\ UNCHANGED n
LastKnown == last \in 0..5
====
