------------------------------ MODULE HourSpec ------------------------------
(* An abstract hour clock with weak fairness, instantiated by              *)
(* ClockRefinement (no .cfg: it is not checked on its own).               *)
EXTENDS Naturals
VARIABLE hr
Init == hr \in 1..12
Next == hr' = IF hr = 12 THEN 1 ELSE hr + 1
Spec == Init /\ [][Next]_hr /\ WF_hr(Next)
=============================================================================
