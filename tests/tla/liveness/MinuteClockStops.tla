---------------------------- MODULE MinuteClockStops ----------------------------
(* The clock of MinuteClock without fairness: it may stop, so the WF_hr   *)
(* part of the refinement property HourSpec fails (by stuttering).       *)
(* Expected: temporal property HourSpec violated.                        *)
EXTENDS Naturals
VARIABLES hr, min
vars == <<hr, min>>
Init == hr = 1 /\ min = 0
Tick == /\ min' = (min + 1) % 3
        /\ hr' = IF min = 2 THEN (hr % 3) + 1 ELSE hr
Spec == Init /\ [][Tick]_vars

HNext == hr' = (hr % 3) + 1
HourSpec == hr \in 1..3 /\ [][HNext]_hr /\ WF_hr(HNext)
TicksForever == []<><<Tick>>_vars
=============================================================================
