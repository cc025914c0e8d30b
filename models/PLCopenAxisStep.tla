--------------------------- MODULE PLCopenAxisStep ---------------------------
(***************************************************************************)
(* RSM-17: the step function by which the SystemStateManager drives each  *)
(* of its axes through the PLCopen single-axis state diagram              *)
(* (docs/design/system-state-manager.md §8, second table).                *)
(*                                                                         *)
(* One definition, shared: PLCopenAxis.tla EXTENDS this module and checks *)
(* the step against the PLCopen legal transitions for every current      *)
(* state, desired state and speed reading; SystemStateManager.tla takes   *)
(* it through INSTANCE.  A constant-level module: no variables.           *)
(***************************************************************************)

AxisStates == {"Disabled", "StandStill", "Homing", "DiscreteMotion",
               "ContinuousMotion", "SynchronizedMotion", "Stopping", "ErrorStop"}

MotionStates == {"ContinuousMotion", "SynchronizedMotion", "DiscreteMotion", "Homing"}

(***************************************************************************)
(* One step of an axis toward the state the manager wants ("des"), given *)
(* the measured speed reading (zero).  Rows in the page's order (first    *)
(* match wins).                                                            *)
(***************************************************************************)
AxisStep(cur, des, zero) ==
    IF      des = "ErrorStop"  THEN "ErrorStop"   \* drive fault
    ELSE IF cur = "ErrorStop"  THEN "ErrorStop"   \* only MC_Reset leaves it
    ELSE IF des = "Disabled"   THEN "Disabled"    \* MC_Power off
    ELSE IF cur = "Disabled"   THEN (IF des = "Stopping" THEN "Disabled" ELSE "StandStill")
                                  \* MC_Stop not accepted in Disabled / MC_Power on
    ELSE IF cur = "Stopping"   THEN (IF des = "Stopping" \/ ~zero THEN "Stopping"
                                                             ELSE "StandStill")
    ELSE IF des = "Stopping"   THEN "Stopping"    \* MC_Stop
    ELSE IF des = "StandStill" THEN (IF cur = "StandStill" THEN "StandStill"
                                                           ELSE "Stopping")
    ELSE IF cur = "Homing"     THEN "Homing"      \* homing is not interrupted
    ELSE des                                      \* CM/SM from StandStill or motion

=============================================================================
