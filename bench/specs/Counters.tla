------------------------------ MODULE Counters ------------------------------
(***************************************************************************)
(* A synthetic benchmark: four independent counters, each stepping up by   *)
(* one modulo its own bound, plus a step that resets the first counter     *)
(* when it equals the second.  Every combination of counter values is      *)
(* reachable, so the state space is the product of the bounds:             *)
(* 40 * 30 * 20 * 70 = 1,680,000 distinct states, with no deadlock.        *)
(*                                                                         *)
(* It measures raw state-space exploration speed: the next-state relation  *)
(* and the invariant are cheap, so the time goes into generating,          *)
(* fingerprinting and storing states.                                      *)
(***************************************************************************)
EXTENDS Naturals

CONSTANTS A, B, C, D

VARIABLES a, b, c, d

vars == <<a, b, c, d>>

Init == a = 0 /\ b = 0 /\ c = 0 /\ d = 0

IncA == a' = (a + 1) % A /\ UNCHANGED <<b, c, d>>
IncB == b' = (b + 1) % B /\ UNCHANGED <<a, c, d>>
IncC == c' = (c + 1) % C /\ UNCHANGED <<a, b, d>>
IncD == d' = (d + 1) % D /\ UNCHANGED <<a, b, c>>

ResetA == a = b /\ a' = 0 /\ UNCHANGED <<b, c, d>>

Next == IncA \/ IncB \/ IncC \/ IncD \/ ResetA

Spec == Init /\ [][Next]_vars

TypeOK == /\ a \in 0..(A - 1)
          /\ b \in 0..(B - 1)
          /\ c \in 0..(C - 1)
          /\ d \in 0..(D - 1)
=============================================================================
