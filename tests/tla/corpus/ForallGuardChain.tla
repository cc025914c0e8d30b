---- MODULE ForallGuardChain ----
\* A guard before a disjunction, inside \A and inside a LET definition used as a
\* conjunct: the disjunction still branches (TLC counts the duplicate steps).
EXTENDS Naturals
VARIABLES x, y
Init == x = 0 /\ y = 0
Next == /\ x < 3
        /\ x' = x + 1
        /\ \A i \in {1, 2} : /\ i > 0
                             /\ \/ TRUE
                                \/ i = 1
        /\ LET ok == /\ x >= 0
                     /\ \/ x = 0
                        \/ TRUE
           IN ok
        /\ y' = y
====
