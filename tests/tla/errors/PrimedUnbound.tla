---------------------------- MODULE PrimedUnbound ----------------------------
(***************************************************************************)
(* (a + 1)' = 1 is not an assignment (its left side is not a variable):   *)
(* TLC evaluates it as a test, and a' has no value yet.                    *)
(* Expected: TLC stops with an evaluation error at the a inside (a + 1)'. *)
(***************************************************************************)
EXTENDS Naturals
VARIABLE a
Init == a = 0
Next == (a + 1)' = 1 /\ a' = 0
=============================================================================
