--------------------- MODULE SystemStateManagerProofs ---------------------
(***************************************************************************)
(* Strengthening invariants for `safestate prove` (proofs/README.md).     *)
(* Each is an invariant of SystemStateManager in its own right; together  *)
(* with TypeOK and the requirement-level properties they make an          *)
(* inductive invariant, so every property is proved for all reachable     *)
(* states and all parameter values.  The lemmas tie the requirement       *)
(* observers (functions of the inputs and outputs) to the manager state.  *)
(***************************************************************************)
EXTENDS SystemStateManager

\* The timers of ARMING and STOPPING never pass their limits: C16 and C20
\* fire when state_cycles reaches the limit, so C17/C21 only count below it,
\* and an escalation (C12-C14 from STOPPING) counts at most up to it.
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
    \* a JOG_STOP's Cat 2 stop (no resume target, K32) is a manual session's (C28)
    /\ state = "STOPPING" /\ stop_category = "CAT2" /\ resume_to = "NONE" =>
           session_mode \in {"T1", "T2"}
    \* K39: a PANIC since the last RELEASED ends every manual powered state
    \* (C11), and Servo-on in T1/T2 is refused while it is remembered
    /\ state \in Powered /\ session_mode \in {"T1", "T2"} => ~enable_release_required

\* The E-stop observer against the manager: no pending demand in IDLE, BOOT
\* and the powered states; a demand means ESTOP_ACTIVE (or lockout), a
\* release ESTOP_RESET_NEEDED (or lockout).  While released but no Reset was
\* queued after the release, every queued RESET is among the stale commands
\* (K36), so K05 cannot accept it.
Strengthen_RESET ==
    /\ state \in Powered \cup {"IDLE", "BOOT"} => obs_estop = "CLEAR"
    /\ obs_estop = "DEMANDED" => state \in {"ESTOP_ACTIVE", "ERROR_LOCKOUT"}
    /\ obs_estop \in {"RELEASED", "RESET_ISSUED"} => state \in {"ESTOP_RESET_NEEDED", "ERROR_LOCKOUT"}
    /\ obs_estop = "RELEASED" /\ state = "ESTOP_RESET_NEEDED" =>
           \A i \in 1..Len(queue) : queue[i].kind = "RESET" => i <= stale_commands
    /\ stale_commands <= Len(queue)
    /\ last_accepted = "RESET" => state = "IDLE"

\* The channel test: no E-stop channel seen open while no demand is pending
\* (K05 clears them); during an episode the manager's memory is the
\* observer's.
Strengthen_TEST ==
    /\ obs_estop = "CLEAR" /\ state # "ERROR_LOCKOUT" => ~estop_tested_a /\ ~estop_tested_b
    /\ obs_estop # "CLEAR" /\ state # "ERROR_LOCKOUT" =>
           (estop_tested_a => obs_open_a) /\ (estop_tested_b => obs_open_b)

\* The input observers count what §3 counts; a fault code shown once is the
\* lockout for good; a fieldbus loss or a failed self-test was a lockout.
Strengthen_OBSERVERS ==
    \* (in lockout the observers latch a count above D, the counters follow
    \* the inputs, which may stop disagreeing)
    /\ state # "ERROR_LOCKOUT" =>
          /\ obs_disagree.estop = estop_mismatch /\ obs_disagree.gate = safeguard_mismatch
          /\ obs_disagree.enable = enabling_mismatch /\ obs_disagree.selector = selector_invalid
    /\ obs_locked <=> state = "ERROR_LOCKOUT"
    /\ obs_fieldbus_lost => state = "ERROR_LOCKOUT"
    /\ obs_self_test_failed => state = "ERROR_LOCKOUT" /\ fault_code = "SELF_TEST_FAILED"
    /\ ~obs_booted => state = "BOOT" /\ ~obs_self_test_failed
    /\ state = "BOOT" => ~obs_booted
    /\ obs_ramp > 0 => state = "STOPPING"
    \* the episode's age is the stop timer's + 1, or one more after an
    \* escalation in the timer's last cycle (C12-C14 cap it; the arm stood)
    /\ obs_ramp > 0 => \/ obs_ramp <= state_cycles + 1
                       \/ /\ obs_ramp = MaxStopCycles + 2 /\ state_cycles = MaxStopCycles
                          /\ stop_category = "CAT1" /\ inputs.speed = "ZERO"
    /\ last_accepted = "PAUSE" => state = "STOPPING" /\ stop_category = "CAT2"
    /\ obs_arming > 0 => state = "ARMING" /\ obs_arming <= state_cycles + 1
    /\ obs_panic <=> enable_release_required
    /\ t2_confirmed => obs_t2 = state_cycles + 1
    /\ state = "IDLE" => state_cycles <= T2ConfirmTimeoutCycles
    \* C30: outside lockout the observers count what the feedback monitors count,
    \* below the latch, and a running count remembers the previous cycle's command
    /\ state # "ERROR_LOCKOUT" =>
          /\ obs_fb_contactor = contactor_fb_cycles /\ obs_fb_brake = brake_fb_cycles
          /\ contactor_fb_cycles <= FeedbackCycles /\ brake_fb_cycles <= FeedbackCycles
          /\ contactor_fb_cycles > 0 => contactor_fb_cmd = obs_was_enabled
          /\ brake_fb_cycles > 0 => brake_fb_cmd = obs_was_released

\* A jog kept for a T1 session was clamped by K29 (the session never
\* changes while a jog is kept: Enter keeps session_mode in powered states).
Strengthen_T1JOG ==
    /\ (session_mode = "T1" /\ jog # NoJog) => jog.speed_mm_s <= T1SpeedLimit
    \* and every kept jog was bounded by K26 (UCA_T2_OVERSPEED after K24)
    /\ jog # NoJog => jog.speed_mm_s <= T2SpeedLimit

\* The jog observer names the axis of the jog the manager keeps (K29 stores
\* the accepted JOG_START's axis; Pause, link loss and Resume keep it; every
\* row that drops the jog shows a Cat 1 stop, accepts the JOG_STOP or removes
\* power, which clears the observer).
Strengthen_JOG ==
    /\ jog # NoJog => obs_jog_axis = jog.axis
    \* (no Cat 1 stop shown where a jog is kept: ARMING starts without a stop
    \* category, K12; OPERATIONAL is entered from ARMING, C15, or from a Cat 2
    \* stop, C28 and K24; K18 and K29 keep it)
    /\ state = "ARMING" => stop_category = "NONE"
    /\ state \in Operational => stop_category \in {"NONE", "CAT2"}

\* Every property of the .cfg at once: each is proved assuming all of them
\* (and the lemmas above) in the pre-state; it is their conjunction that is
\* inductive.
Strengthen_ALL ==
    /\ TypeOK
    /\ INV_RESET /\ RSM05_RESET_ACCEPTED /\ RSM04_CHANNEL_TEST /\ RSM03_ESTOP_CAT0
    /\ INV_DISCREPANCY /\ RSM03_FIELDBUS /\ RSM02_MODE_CHANGE /\ INV_GATE /\ INV_ENABLE
    /\ RSM11_STOP_BUDGET /\ RSM11_PAUSE_CAT2 /\ RSM11_STANDSTILL /\ INV_NOJOG_AUTO
    /\ RSM09_JOG_START /\ RSM08_START /\ INV_T1SPEED /\ RSM06_SERVO_ON
    /\ RSM07_DRIVE_FAULT /\ RSM12_SELF_TEST /\ RSM17_AXES /\ INV_1OO2
    /\ RSM07_ARMING_TIMEOUT /\ RSM13_RESULT /\ RSM14_QUEUE /\ RSM13_LINK_LOSS
    /\ UCA_BRAKE_ORDER /\ UCA_READY_LOST /\ UCA_PANIC_REARM /\ UCA_T2_OVERSPEED
    /\ UCA_FEEDBACK /\ UCA_FEEDBACK_CAUSE /\ UCA_DISCREPANCY_CAUSE /\ UCA_JOG_AXIS
    /\ UCA_STOP_POWER_AT_STANDSTILL
=============================================================================
