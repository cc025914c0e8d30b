---------------------------- MODULE DoneDetection ----------------------------
(* Abstract termination detection: once x reaches 0, done must be set.     *)
(* Refined by RefineDoneEnabled, which substitutes an expression for done. *)
EXTENDS Naturals
VARIABLES x, done
vars == <<x, done>>
Init == x \in 0..2 /\ done = FALSE
Dec == x > 0 /\ x' = x - 1 /\ UNCHANGED done
Detect == x = 0 /\ done' = TRUE /\ UNCHANGED x
Next == Dec \/ Detect
Spec == Init /\ [][Next]_vars /\ WF_vars(Detect) /\ WF_vars(Dec)
=============================================================================
