------------------------------ MODULE HourClock ------------------------------
(* The hour clock of Specifying Systems ch. 2, with the liveness property *)
(* of ch. 8 (WF and <>) in the spec; this cfg checks safety only (the    *)
(* published cfg also has PROPERTY, which needs liveness checking).       *)
(* TLC: success.                                                          *)
EXTENDS Naturals
VARIABLE hr
HCini == hr \in (1 .. 12)
HCnxt == hr' = IF hr # 12 THEN hr + 1 ELSE 1
HC == HCini /\ [][HCnxt]_hr
LSpec == HC /\ WF_hr(HCnxt)
AlwaysTick == \A n \in 1..12 : (hr = n) ~> (hr # n)
HCtypeOK == hr \in (1 .. 12)
=============================================================================
