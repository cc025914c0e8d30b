---------------------------- MODULE CaseNoMatch ----------------------------
(* A CASE without OTHER whose arms cover only 0..2; when the counter       *)
(* reaches 3 no arm matches.  Expected: evaluation error at line 11.       *)
EXTENDS Naturals

VARIABLE n

Init == n = 0

Next == /\ n' = n + 1
        /\ CASE n = 0 -> TRUE
             [] n = 1 -> TRUE
             [] n = 2 -> TRUE
=============================================================================
