----------------------- MODULE SafetyServiceProofs -----------------------
(***************************************************************************)
(* Strengthening invariants for `safestate prove` (proofs/README.md).     *)
(* The conjunction of the .cfg's invariants, with TypeOK, is inductive:   *)
(* every INV_SAF_* holds in all reachable states for every value of the   *)
(* timeout constants.                                                      *)
(***************************************************************************)
EXTENDS SafetyService

\* The invariants of the .cfg support each other: INV_SAF_EMERGENCY needs
\* INV_SAF_FAULT_ABSORBING (a faulted service is in FAULT, never left by
\* M01) and INV_SAF_RELEASE_ONLY_OPERATIONAL (control is wanted in every
\* emergency-raising state).
Strengthen_ALL ==
    /\ INV_SAF_EMERGENCY
    /\ INV_SAF_RELEASE_ONLY_OPERATIONAL
    /\ INV_SAF_NO_OPERATIONAL_IN_DANGER
    /\ INV_SAF_FAULT_ABSORBING
    /\ INV_SAF_SET_STATE_WITH_CONTROL
=============================================================================
