---- MODULE RecordAssignment ----
\* x' \in [f : S, g : T] with fields not in alphabetical order: the first successor
\* that violates the invariant, and so the trace, depends on the enumeration order
\* (the product of the fields' sets, the last field turning fastest), which is not
\* TLC's order of the records here ("alpha" comes first in the module: its rank is lower).
EXTENDS Naturals
VARIABLES msg, step
Init == msg = [alpha |-> "none", zeta |-> 0] /\ step = 0
Next == /\ step < 2
        /\ msg' \in [zeta : {6, 3}, alpha : {"c", "a"}]
        /\ step' = step + 1
Fine == step = 0 \/ (msg.zeta /= 6 /\ msg.alpha /= "c")
====
