----------------------------- MODULE HourClock -----------------------------
(***************************************************************************)
(* A twelve-hour clock that shows only the hour.  This module has no .cfg: *)
(* it is a building block instantiated by Clock.                           *)
(***************************************************************************)
EXTENDS Naturals

VARIABLE hr

HCInit == hr \in 1..12

HCNext == hr' = IF hr = 12 THEN 1 ELSE hr + 1
=============================================================================
