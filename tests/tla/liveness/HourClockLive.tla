--------------------------- MODULE HourClockLive ---------------------------
(* An hour clock with weak fairness on its tick: it strikes one infinitely *)
(* often, and from any hour the next noon comes.  Expected: success.      *)
EXTENDS Naturals
VARIABLE hr
Init == hr \in 1..12
Tick == hr' = IF hr = 12 THEN 1 ELSE hr + 1
Spec == Init /\ [][Tick]_hr /\ WF_hr(Tick)

StrikesOne == []<>(hr = 1)
NoonComes == (hr = 6) ~> (hr = 12)
Live == StrikesOne /\ NoonComes
=============================================================================
