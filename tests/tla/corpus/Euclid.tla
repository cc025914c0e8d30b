------------------------------- MODULE Euclid -------------------------------
(***************************************************************************)
(* Subtractive Euclid from every pair of starting values in 1..N: while    *)
(* the two numbers differ, subtract the smaller from the larger.  The GCD  *)
(* is preserved throughout, which the invariant checks against two         *)
(* independent definitions.  Each run ends in a state with a = b, where    *)
(* no step is enabled: that is the intended end, so the cfg turns deadlock *)
(* checking off.                                                           *)
(*                                                                         *)
(* Exercises: EXTENDS of a sibling library module, RECURSIVE operators,    *)
(* CHOOSE, a recursive function, CHECK_DEADLOCK FALSE, many initial        *)
(* states.  Expected: success.                                             *)
(***************************************************************************)
EXTENDS Naturals, NumberTheory

CONSTANT N

VARIABLES a0, b0, a, b

Init ==
    /\ a0 \in 1..N
    /\ b0 \in 1..N
    /\ a = a0
    /\ b = b0

Next ==
    \/ /\ a > b
       /\ a' = a - b
       /\ UNCHANGED <<a0, b0, b>>
    \/ /\ b > a
       /\ b' = b - a
       /\ UNCHANGED <<a0, b0, a>>

GcdPreserved == Gcd(a, b) = Gcd(a0, b0)

\* The expensive check only at the end of each run.
Correct == a = b => a = GcdSpec(a0, b0)

Misc == /\ Fact[Bits(a)] >= 1
        /\ Fact[5] = 120
        /\ Bits(8) = 4
=============================================================================
