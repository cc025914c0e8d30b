----------------------------- MODULE PLCopenAxis -----------------------------
(***************************************************************************)
(* RSM-17: the PLCopen single-axis state machine (PLCopen Motion Control  *)
(* part 1, the axis state diagram) and the step function by which the     *)
(* SystemStateManager drives each of its six axes                         *)
(* (docs/design/system-state-manager.md §8).                              *)
(*                                                                         *)
(* At the end of every cycle the manager computes the axis state its own  *)
(* state wants ("desired") and each axis takes one step toward it:        *)
(* axis' = AxisStep(axis, desired, speed_zero).  This model checks that   *)
(* step function for EVERY current state (also Homing and DiscreteMotion, *)
(* which the manager itself never commands), every desired state and     *)
(* both speed readings: each step is a legal PLCopen transition, a stop   *)
(* takes enabled axes through Stopping to StandStill, and a drive fault   *)
(* puts the axis in ErrorStop.  AxisStep itself is in                    *)
(* PLCopenAxisStep.tla, which SystemStateManager.tla takes by INSTANCE.    *)
(***************************************************************************)
EXTENDS PLCopenAxisStep

\* The states the manager may ask for (§8, first table).
DesiredStates == {"Disabled", "ErrorStop", "StandStill", "ContinuousMotion",
                  "SynchronizedMotion", "Stopping"}

(***************************************************************************)
(* The legal transitions of the PLCopen state diagram (besides staying):  *)
(*  - any state -> ErrorStop (an axis error);                              *)
(*  - any state but ErrorStop -> Disabled (MC_Power.Enable = FALSE with no *)
(*    error in the axis);                                                  *)
(*  - ErrorStop -> Disabled / StandStill (MC_Reset, power off / on);       *)
(*  - Disabled -> StandStill (MC_Power on);                                *)
(*  - StandStill -> Homing, DiscreteMotion, ContinuousMotion,              *)
(*    SynchronizedMotion, Stopping;                                        *)
(*  - Homing -> StandStill (done), Stopping (MC_Stop);                     *)
(*  - DiscreteMotion -> StandStill (done);                                 *)
(*  - Discrete/Continuous/SynchronizedMotion -> any of the three, Stopping;*)
(*  - Stopping -> StandStill (done and Execute = FALSE).                   *)
(***************************************************************************)
Moving3 == {"DiscreteMotion", "ContinuousMotion", "SynchronizedMotion"}

LegalTransitions ==
       {<<s, "ErrorStop">> : s \in AxisStates}
  \cup {<<s, "Disabled">> : s \in AxisStates \ {"ErrorStop"}}
  \cup {<<"ErrorStop", "Disabled">>, <<"ErrorStop", "StandStill">>,
        <<"Disabled", "StandStill">>}
  \cup {<<"StandStill", t>> : t \in {"Homing", "Stopping"} \cup Moving3}
  \cup {<<"Homing", "StandStill">>, <<"Homing", "Stopping">>,
        <<"DiscreteMotion", "StandStill">>}
  \cup {<<s, t>> : s \in Moving3, t \in Moving3 \cup {"Stopping"}}
  \cup {<<"Stopping", "StandStill">>}

Legal(from, to) == from = to \/ <<from, to>> \in LegalTransitions

-----------------------------------------------------------------------------
VARIABLES
    axis,        \* the axis state after the step
    prev,        \* the axis state before the step
    desired,     \* the state the manager asked for in this step ("NONE" before)
    speed_zero   \* the measured speed reading of this step (speed = ZERO)

vars == <<axis, prev, desired, speed_zero>>

\* The axis starts in any state (also Homing and DiscreteMotion, which the
\* manager never commands, so that the whole table is exercised); no step
\* has been taken yet (desired = "NONE").
Init ==
    /\ axis \in AxisStates
    /\ prev = axis
    /\ desired = "NONE"
    /\ speed_zero = TRUE

\* The manager may ask for anything; the measured speed is free.
Step(d, z) ==
    /\ prev' = axis
    /\ desired' = d
    /\ speed_zero' = z
    /\ axis' = AxisStep(axis, d, z)

Next == \E d \in DesiredStates, z \in BOOLEAN : Step(d, z)

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
TypeOK ==
    /\ axis \in AxisStates /\ prev \in AxisStates
    /\ desired \in DesiredStates \cup {"NONE"} /\ speed_zero \in BOOLEAN

\* RSM-17: every step taken is a legal PLCopen transition.
INV_LEGAL == Legal(prev, axis)

\* RSM-17: a drive fault puts the axis in ErrorStop, and nothing but
\* MC_Reset (never issued by the manager) leaves it.
INV_ERRORSTOP == (desired = "ErrorStop" \/ prev = "ErrorStop") => axis = "ErrorStop"

\* RSM-17: a stop takes every enabled axis to Stopping (MC_Stop) ...
INV_STOP_ENABLED ==
    (desired = "Stopping" /\ prev \notin {"Disabled", "ErrorStop"}) => axis = "Stopping"

\* ... a moving axis reaches StandStill only through Stopping ...
INV_STOP_VIA_STOPPING == prev \in MotionStates => axis # "StandStill"

\* ... it leaves Stopping only at rest ...
INV_STOPPING_ZERO == (prev = "Stopping" /\ axis = "StandStill") => speed_zero

\* ... and at rest it does reach StandStill when no longer asked to stop.
INV_STOP_COMPLETES ==
    (/\ prev = "Stopping" /\ speed_zero
     /\ desired \in {"StandStill", "ContinuousMotion", "SynchronizedMotion"})
        => axis = "StandStill"

\* Power off (§8: MC_Power off) disables every axis without an error.
INV_POWER_OFF == (desired = "Disabled" /\ prev # "ErrorStop") => axis = "Disabled"

=============================================================================
