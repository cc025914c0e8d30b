---------------------------- MODULE MinuteClock ----------------------------
(* A clock of 3 hours of 3 minutes with weak fairness on its tick.  As a    *)
(* refinement check, its hour hand must behave as HourSpec, an hour clock  *)
(* with its own initial condition, step and weak fairness (a PROPERTY that *)
(* mixes a state predicate, [][A]_v and WF_v(A)); it ticks forever        *)
(* ([]<><<Tick>>_vars).  Expected: success.                                *)
EXTENDS Naturals
VARIABLES hr, min
vars == <<hr, min>>
Init == hr = 1 /\ min = 0
Tick == /\ min' = (min + 1) % 3
        /\ hr' = IF min = 2 THEN (hr % 3) + 1 ELSE hr
Spec == Init /\ [][Tick]_vars /\ WF_vars(Tick)

HNext == hr' = (hr % 3) + 1
HourSpec == hr \in 1..3 /\ [][HNext]_hr /\ WF_hr(HNext)
TicksForever == []<><<Tick>>_vars
=============================================================================
