--------------------------- MODULE ClockRefinement ---------------------------
(* A clock of hours and (4) quarters with weak fairness refines the       *)
(* abstract HourSpec through an instance: PROPERTY Refinement == H!Spec    *)
(* (its initial condition, its step as [][Next]_hr and its WF_hr(Next)).   *)
(* Expected: success.                                                      *)
EXTENDS Naturals
VARIABLES hour, quarter
vars == <<hour, quarter>>
H == INSTANCE HourSpec WITH hr <- hour
Init == hour = 12 /\ quarter = 0
Tick == /\ quarter' = (quarter + 1) % 4
        /\ hour' = IF quarter = 3 THEN (IF hour = 12 THEN 1 ELSE hour + 1) ELSE hour
Spec == Init /\ [][Tick]_vars /\ WF_vars(Tick)
Refinement == H!Spec
=============================================================================
