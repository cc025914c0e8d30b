--------------------- MODULE SystemStateManagerProofs ---------------------
(***************************************************************************)
(* Strengthening invariants for `safestate prove` (proofs/README.md).     *)
(* Each is an invariant of SystemStateManager in its own right; together  *)
(* with TypeOK and the INV_* they make an inductive invariant, so every   *)
(* INV_* is proved for all reachable states and all parameter values.     *)
(***************************************************************************)
EXTENDS SystemStateManager

\* The timers of ARMING and STOPPING never pass their limits: C16 and C20
\* fire when state_cycles reaches the limit, so C17/C21 only count below it.
\* (TypeOK's range 0..Max2(...) alone is not inductive: in ARMING a counter
\* above ArmingTimeoutCycles but below MaxStopCycles would count on.)
Strengthen_TIMERS ==
    /\ state = "ARMING"   => state_cycles <= ArmingTimeoutCycles
    /\ state = "STOPPING" => state_cycles <= MaxStopCycles

\* The sub-states of OPERATIONAL, and the state a pause resumes to, match
\* the session mode latched by Servo-on (C15 picks AUTO_IDLE/MANUAL_IDLE
\* by session_mode; K18 starts only from AUTO_IDLE, K29 only from
\* MANUAL_IDLE; K20 records the motion state being paused).
Strengthen_MODE ==
    /\ state \in {"AUTO_IDLE", "AUTO_RUNNING"} => session_mode = "AUTO"
    /\ state \in {"MANUAL_IDLE", "MANUAL_JOGGING"} => session_mode \in {"T1", "T2"}
    /\ resume_to = "AUTO_RUNNING" => session_mode = "AUTO"
    /\ resume_to = "MANUAL_JOGGING" => session_mode \in {"T1", "T2"}
    /\ state = "STOPPING" => stop_category \in {"CAT1", "CAT2"}

\* reset_since_trip is FALSE only between an E-stop trip and the next
\* accepted Reset, i.e. only in ESTOP_ACTIVE, ESTOP_RESET_NEEDED and
\* ERROR_LOCKOUT: every way into IDLE and the powered states keeps it.
Strengthen_RESET ==
    state \in Powered \cup {"IDLE", "BOOT"} => reset_since_trip

\* A jog kept for a T1 session was clamped by K29 (the session never
\* changes while a jog is kept: Enter keeps session_mode in powered states).
Strengthen_T1JOG ==
    (session_mode = "T1" /\ jog # NoJog) => jog.speed_mm_s <= T1SpeedLimit

\* Every invariant of the .cfg at once: each INV_* is proved assuming all
\* of them (and the lemmas above) in the pre-state; it is their conjunction
\* that is inductive.
Strengthen_ALL ==
    /\ TypeOK
    /\ INV_RESET /\ INV_NOJOG_AUTO /\ INV_DISCREPANCY /\ INV_POWER
    /\ INV_GATE /\ INV_ENABLE /\ INV_T1SPEED /\ INV_1OO2
=============================================================================
