------------------------------- MODULE Clock -------------------------------
(***************************************************************************)
(* A clock with hours and minutes, built on HourClock: the hour hand is an *)
(* instance of HourClock whose variable hr is substituted by our hour.     *)
(* The clock starts at any hour, on the hour, and runs forever.            *)
(*                                                                         *)
(* Exercises: INSTANCE ... WITH, using an instance's operators (H!HCNext), *)
(* % and \div, [Next]_vars, SPECIFICATION, an invariant over a derived     *)
(* quantity.  Expected: success; 720 distinct states, the state graph is   *)
(* a single cycle reached from 12 initial states.                          *)
(***************************************************************************)
EXTENDS Naturals

VARIABLES hour, minute

vars == <<hour, minute>>

H == INSTANCE HourClock WITH hr <- hour

Init == H!HCInit /\ minute = 0

Tick ==
    /\ minute' = (minute + 1) % 60
    /\ IF minute = 59 THEN H!HCNext ELSE UNCHANGED hour

Next == Tick

Spec == Init /\ [][Next]_vars

\* Minutes since 12:00, computed two ways.
MinutesOfDay == (hour % 12) * 60 + minute
TypeOK == hour \in 1..12 /\ minute \in 0..59
Consistent == /\ MinutesOfDay \div 60 = hour % 12
              /\ MinutesOfDay % 60 = minute
=============================================================================
