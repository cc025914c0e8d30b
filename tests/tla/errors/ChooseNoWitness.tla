-------------------------- MODULE ChooseNoWitness --------------------------
(* CHOOSE over a set none of whose elements satisfies the predicate.  TLC  *)
(* cannot pick a value and stops.  Expected: evaluation error at line 10   *)
(* in the initial predicate.                                               *)
EXTENDS Naturals

VARIABLE x

Init ==
    x = CHOOSE n \in 1..3 : n > 5

Next == UNCHANGED x
=============================================================================
