------------------------------ MODULE Untyped ------------------------------
EXTENDS Naturals
VARIABLES x, log
Init == x = 0 /\ log = [last |-> 0]
Next == x' = x + 1 /\ log' = [last |-> x]
\* log is not typed: it may be assigned, never read.
TypeOK == x \in Nat
Reads == log.last <= x
Fine == x >= 0
=============================================================================
