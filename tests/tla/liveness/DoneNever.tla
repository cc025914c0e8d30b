---------------------------- MODULE DoneNever --------------------------------
(* DoneDetection with a Detect step that can never happen (for           *)
(* RefineDoneNever: ENABLED of it is FALSE).                             *)
EXTENDS Naturals
VARIABLES x, done
vars == <<x, done>>
Init == x \in 0..2 /\ done = FALSE
Dec == x > 0 /\ x' = x - 1 /\ UNCHANGED done
Detect == x = 0 /\ done' = TRUE /\ done' = FALSE /\ UNCHANGED x
Next == Dec \/ Detect
Spec == Init /\ [][Next]_vars /\ WF_vars(Detect) /\ WF_vars(Dec)
=============================================================================
