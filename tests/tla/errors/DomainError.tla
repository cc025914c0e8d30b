---------------------------- MODULE DomainError ----------------------------
(* A function with domain 1..3 is applied to 4 once the index walks off    *)
(* its end.  Expected: evaluation error at line 14, in the third state.    *)
EXTENDS Naturals

VARIABLES i, sum

Weights == [k \in 1..3 |-> 10 * k]

Init == i = 1 /\ sum = 0

Next == /\ i' = i + 1
        /\ sum' = sum + Weights[i]
        /\ Weights[i'] > 0
=============================================================================
