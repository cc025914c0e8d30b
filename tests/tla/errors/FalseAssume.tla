---------------------------- MODULE FalseAssume ----------------------------
(* An ASSUME that the cfg's constants contradict: TLC checks assumptions   *)
(* before computing the initial states and stops.  Expected: the ASSUME    *)
(* at line 8 is reported false.                                            *)
EXTENDS Naturals

CONSTANTS Low, High
ASSUME Low < High

VARIABLE x

Init == x \in Low..High

Next == UNCHANGED x
=============================================================================
