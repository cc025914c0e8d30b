--------------------------- MODULE ClockRefinementStops ---------------------------
(* The clock of ClockRefinement without fairness: it may stop, so it does *)
(* not refine HourSpec, whose hour hand must keep moving (WF_hr(Next)).   *)
(* Expected: temporal property Refinement violated (by stuttering).       *)
EXTENDS Naturals
VARIABLES hour, quarter
vars == <<hour, quarter>>
H == INSTANCE HourSpec WITH hr <- hour
Init == hour = 12 /\ quarter = 0
Tick == /\ quarter' = (quarter + 1) % 4
        /\ hour' = IF quarter = 3 THEN (IF hour = 12 THEN 1 ELSE hour + 1) ELSE hour
Spec == Init /\ [][Tick]_vars
Refinement == H!Spec
=============================================================================
