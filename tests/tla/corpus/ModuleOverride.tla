--------------------------- MODULE ModuleOverride ---------------------------
(* Two pumps built from module PumpLimits.  The .cfg says                   *)
(*     MaxSpeed <- [PumpLimits] TestMax                                     *)
(* so both instances' MaxSpeed is this module's TestMax (3), not 2; the   *)
(* invariant Slow (a < 3) is then violated.  TLC 1.8.0: Slow violated    *)
(* after 10 states generated, 7 distinct, depth 4, a 4-state trace.      *)
EXTENDS Naturals
VARIABLES a, b
P == INSTANCE PumpLimits WITH speed <- a
Q == INSTANCE PumpLimits WITH speed <- b
TestMax == 3

Init == a = 0 /\ b = 0
Next == \/ (P!Up \/ P!Down) /\ UNCHANGED b
        \/ (Q!Up \/ Q!Down) /\ UNCHANGED a
Slow == a < 3
=============================================================================
