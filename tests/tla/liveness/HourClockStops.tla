--------------------------- MODULE HourClockStops ---------------------------
(* The hour clock without fairness: it may stop at any hour, so []<>(hr=1) *)
(* fails by stuttering.  Expected: temporal property violated.            *)
EXTENDS Naturals
VARIABLE hr
Init == hr = 1
Tick == hr' = IF hr = 12 THEN 1 ELSE hr + 1
Spec == Init /\ [][Tick]_hr

StrikesOne == []<>(hr = 1)
=============================================================================
