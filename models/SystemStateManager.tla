------------------------- MODULE SystemStateManager -------------------------
(***************************************************************************)
(* The SystemStateManager of a 6-axis industrial robot (RSM-01 .. RSM-17), *)
(* modelled row by row after docs/design/system-state-manager.md ("the     *)
(* page"; section numbers below refer to it).                              *)
(*                                                                         *)
(* One step of this spec is exactly one event the C++ accepts (page §1):   *)
(*   Cycle(in)   -- SystemStateManager::cycle(ScanInputs), abstract inputs *)
(*   Submit(cmd) -- SystemStateManager::submit(Command)                    *)
(* The variable `event` records the event that produced each state, so a   *)
(* trace is a script of C++ calls; models/README.md gives the mapping.     *)
(*                                                                         *)
(* A cycle is the sequential composition  §3 channel monitoring ; §5       *)
(* safety rows ; §6 one command ; §8 axes.  TLA+ has no sequential         *)
(* composition of actions, so every section is a pure function from a      *)
(* manager record to a manager record, every row is one small named        *)
(* operator (row id in its name), and the event assigns the result to the  *)
(* variables.  Consequently each event has exactly one successor (see      *)
(* Determinism below).                                                     *)
(***************************************************************************)
EXTENDS Integers, Sequences, FiniteSets

-----------------------------------------------------------------------------
(*************************** Parameters (§9) ******************************)
CONSTANTS
    DiscrepancyCycles,    \* D, Config::discrepancy_cycles (RSM-04, RSM-02)
    ArmingTimeoutCycles,  \* Config::arming_timeout_cycles (RSM-07)
    MaxStopCycles,        \* Config::max_stop_cycles (RSM-11)
    T2ConfirmTimeoutCycles, \* Config::t2_confirm_timeout_cycles (C22: a T2 confirmation expires)
    T1SpeedLimit,         \* Config::t1_speed_limit_mm_s (RSM-10)
    T2SpeedLimit,         \* Config::t2_speed_limit_mm_s (K26: the largest jog speed accepted)
    QueueCapacity,        \* Config::command_queue_limit (RSM-14)
    FeedbackCycles,       \* Config::feedback_allowed_cycles (C30: a feedback's switching time)
    JogCommands           \* the JOG_START commands the operator may submit

(* The input values the environment may present (restricts the input      *)
(* space of a run; the full space is given by the type Inputs below).     *)
CONSTANTS
    EstopInputs,          \* set of <<estop_a, estop_b>>  (TRUE = NC contact closed)
    SafeguardInputs,      \* set of <<gate_a, gate_b>>    (TRUE = closed / clear)
    EnablingInputs,       \* set of <<enable_a, enable_b>>
    SelectorInputs,       \* subset of Selectors
    SpeedInputs,          \* subset of Speeds
    ServoReadyInputs,     \* subset of BOOLEAN
    DriveFaultInputs,     \* subset of BOOLEAN
    SelfTestInputs,       \* subset of BOOLEAN
    FieldbusInputs,       \* subset of BOOLEAN (C24: FALSE = fieldbus/cycle watchdog lost)
    FeedbackInputs,       \* TRUE: contactor / brake feedback may disagree with the command
    LockoutHoldsInputs,   \* TRUE: the held signals stop changing in ERROR_LOCKOUT
    CombineChanges        \* TRUE: a held change and free choices in one cycle

D == DiscrepancyCycles

\* ISO 10218-1 5.7.3 (RSM-10): reduced speed is at most 250 mm/s at the TCP,
\* whatever Config::t1_speed_limit_mm_s says (the properties use this bound).
T1MaxSpeed == 250

EnablePositions == {"RELEASED", "MIDDLE", "PANIC"}
Selectors       == {"AUTO", "T1", "T2", "INVALID"}
\* OVER_T2: the TCP speed above Config::t2_speed_limit_mm_s (so above T1's too).
Speeds          == {"ZERO", "MOVING", "OVER_T1", "OVER_T2"}
Modes           == {"AUTO", "T1", "T2"}

CommandKinds == {"RESET", "SERVO_ON", "SERVO_OFF", "START", "PAUSE", "RESUME",
                 "JOG_START", "JOG_STOP", "T2_CONFIRM"}

\* A command record (C++: Command). Commands other than JOG_START carry 0s.
CommandType == [kind: CommandKinds, axis: Int, direction: Int, speed_mm_s: Int]
Simple(k)   == [kind |-> k, axis |-> 0, direction |-> 0, speed_mm_s |-> 0]
Commands    == {Simple(k) : k \in CommandKinds \ {"JOG_START"}} \cup JogCommands

\* The levels the environment holds before the first cycle (all healthy,
\* enabling device released, selector on AUTO, robot at rest).
InitialInputs == [estop_a |-> TRUE, estop_b |-> TRUE,
                  gate_a |-> TRUE, gate_b |-> TRUE,
                  enable_a |-> "RELEASED", enable_b |-> "RELEASED",
                  selector |-> "AUTO", self_test_ok |-> TRUE,
                  servo_ready |-> FALSE, drive_fault |-> FALSE, speed |-> "ZERO",
                  fieldbus_ok |-> TRUE, operator_link_ok |-> TRUE,
                  contactor_fb |-> FALSE, brake_fb |-> FALSE]

ASSUME DiscrepancyCycles   \in Nat \ {0}
ASSUME ArmingTimeoutCycles \in Nat \ {0}
ASSUME MaxStopCycles       \in Nat \ {0}
ASSUME T1SpeedLimit        \in 1..T1MaxSpeed   \* ISO 10218-1 5.7.3: at most 250 mm/s
\* Config::validate (page §9 "Configuration bounds"): every timer at most
\* kMaxTimerCycles, the T1 limit at most ISO 10218-1's reduced speed.
ASSUME DiscrepancyCycles   <= 2147483647
ASSUME ArmingTimeoutCycles <= 2147483647
ASSUME MaxStopCycles       <= 2147483647
ASSUME T2ConfirmTimeoutCycles \in Nat \ {0} /\ T2ConfirmTimeoutCycles <= 2147483647
ASSUME T2SpeedLimit \in Nat /\ T1SpeedLimit < T2SpeedLimit /\ T2SpeedLimit <= 3000
ASSUME QueueCapacity       \in 1..16      \* at most the compile-time capacity
ASSUME FeedbackCycles      \in 0..1000    \* kMaxFeedbackCycles (Config::validate)
ASSUME FeedbackInputs      \in BOOLEAN
ASSUME JogCommands \subseteq [kind: {"JOG_START"}, axis: Int, direction: Int,
                              speed_mm_s: Int]
ASSUME EstopInputs      \subseteq BOOLEAN \X BOOLEAN
ASSUME SafeguardInputs  \subseteq BOOLEAN \X BOOLEAN
ASSUME EnablingInputs   \subseteq EnablePositions \X EnablePositions
ASSUME SelectorInputs   \subseteq Selectors
ASSUME SpeedInputs      \subseteq Speeds
ASSUME ServoReadyInputs \subseteq BOOLEAN
ASSUME DriveFaultInputs \subseteq BOOLEAN
ASSUME SelfTestInputs   \subseteq BOOLEAN
ASSUME FieldbusInputs   \subseteq BOOLEAN
ASSUME LockoutHoldsInputs \in BOOLEAN
ASSUME CombineChanges \in BOOLEAN
ASSUME /\ <<TRUE, TRUE>> \in EstopInputs
       /\ <<TRUE, TRUE>> \in SafeguardInputs
       /\ <<"RELEASED", "RELEASED">> \in EnablingInputs
       /\ "AUTO" \in SelectorInputs /\ "ZERO" \in SpeedInputs
       /\ FALSE \in ServoReadyInputs /\ TRUE \in ServoReadyInputs
       /\ FALSE \in DriveFaultInputs
       /\ TRUE \in SelfTestInputs /\ TRUE \in FieldbusInputs

-----------------------------------------------------------------------------
(***************************** Value sets (§4-§8) *************************)
\* RSM-01: the manager's states (OPERATIONAL = the four AUTO_/MANUAL_ sub-states).
States == {"BOOT", "ERROR_LOCKOUT", "ESTOP_ACTIVE", "ESTOP_RESET_NEEDED", "IDLE",
           "ARMING", "AUTO_IDLE", "AUTO_RUNNING", "MANUAL_IDLE", "MANUAL_JOGGING",
           "STOPPING", "HOLD"}
Operational == {"AUTO_IDLE", "AUTO_RUNNING", "MANUAL_IDLE", "MANUAL_JOGGING"}
Powered     == {"ARMING", "STOPPING", "HOLD"} \cup Operational          \* §4
Motion      == {"AUTO_RUNNING", "MANUAL_JOGGING"}                       \* §4

StopCategories == {"NONE", "CAT0", "CAT1", "CAT2"}
FaultCodes == {"NONE", "SELF_TEST_FAILED", "DISCREPANCY_ESTOP",
               "DISCREPANCY_SAFEGUARD", "DISCREPANCY_ENABLING", "SELECTOR_INVALID",
               "DRIVE_FAULT", "T1_OVERSPEED", "ARMING_TIMEOUT", "STOP_TIMEOUT",
               "FIELDBUS_LOSS", "STANDSTILL_VIOLATION", "SERVO_READY_LOST",
               "T2_OVERSPEED", "CONTACTOR_FEEDBACK", "BRAKE_FEEDBACK"}
Reasons == {"LOCKED_OUT", "ESTOP_PRESSED", "WRONG_STATE", "DRIVE_FAULT",
            "SELECTOR_INVALID", "SAFEGUARD_OPEN", "ENABLE_NOT_MIDDLE",
            "T2_NOT_CONFIRMED", "WRONG_MODE", "JOG_IN_AUTO", "INVALID_ARGUMENT",
            "QUEUE_FULL", "CHANNEL_TEST_PENDING"}
\* §8: the PLCopen axis states and the step function, shared with
\* PLCopenAxis.tla (which checks the step against the PLCopen diagram).
PLCopen == INSTANCE PLCopenAxisStep
Axes == 1..6
\* The robot's six joints (a 6-axis arm, §8; ScanOutputs::axes): what the
\* properties hold the model's Axes and the commands' axis numbers against.
RobotJoints == 1..6

NoJog == [axis |-> 0, direction |-> 0, speed_mm_s |-> 0]

\* The abstract inputs of one cycle (§2, "derived each cycle").
Inputs == [estop_a: BOOLEAN, estop_b: BOOLEAN, gate_a: BOOLEAN, gate_b: BOOLEAN,
           enable_a: EnablePositions, enable_b: EnablePositions,
           selector: Selectors, self_test_ok: BOOLEAN, servo_ready: BOOLEAN,
           drive_fault: BOOLEAN, speed: Speeds, fieldbus_ok: BOOLEAN,
           operator_link_ok: BOOLEAN,
           contactor_fb: BOOLEAN,   \* the safety relay's auxiliary contact: closed
           brake_fb: BOOLEAN]       \* the brakes' feedback: released

Min(a, b) == IF a <= b THEN a ELSE b
Max2(a, b) == IF a >= b THEN a ELSE b

-----------------------------------------------------------------------------
(******************************* Variables *********************************)
(* Manager state: named exactly as the §7 status/output keys.             *)
VARIABLES
    state, selector, session_mode, stop_category, fault_code,
    last_reject_reason, command_result,
    estop_mismatch, safeguard_mismatch, enabling_mismatch, selector_invalid,
    state_cycles, t2_confirmed, resume_to, jog, queue, axes,
    stale_commands,       \* K36: queued commands submitted before the last E-stop release
    estop_tested_a,       \* K37: E-stop channel A seen open since the last accepted Reset
    estop_tested_b,       \* K37: likewise channel B
    enable_release_required, \* K39: PANIC seen since the enabling device was last RELEASED
    contactor_fb_cycles,  \* C30: consecutive cycles the contactor feedback disagreed
    brake_fb_cycles,      \* C30: likewise the brake feedback
    contactor_fb_cmd,     \* the contactor command of the last disagreeing cycle
    brake_fb_cmd          \* the brake command of the last disagreeing cycle

(* Environment: `inputs` -- the inputs of the last cycle (before the     *)
(* first cycle: InitialInputs); `event` -- the event that produced this  *)
(* state (not in View).                                                   *)
VARIABLES inputs, event

(* Requirement observers (not C++ state).  Each is a function of the      *)
(* input history, the command stream and the outputs/status record only   *)
(* (never of `state` or another model-internal variable), so that the     *)
(* requirement-level invariants below say what REQUIREMENTS.md says and a *)
(* weakened model cannot satisfy them by construction.                   *)
(*   obs_estop     -- RSM-05: "CLEAR"; "DEMANDED" from a cycle with either *)
(*                    E-stop channel open; "RELEASED" from the next cycle  *)
(*                    with both closed; "RESET_ISSUED" when a RESET is     *)
(*                    submitted (queued) after that; "CLEAR" again when a  *)
(*                    cycle pops a RESET and reports ACCEPTED then.         *)
(*   obs_open_a/b  -- RSM-04 channel test: channel seen open since the    *)
(*                    last CLEAR.                                          *)
(*   obs_disagree  -- RSM-04/02: consecutive cycles the inputs disagreed  *)
(*                    (pairs) or read an invalid selector; latched at D+1  *)
(*                    (a disagreement that lasted D+1 cycles was read).    *)
(*   obs_locked    -- RSM-04: a fault code was ever output.               *)
(*   obs_ramp      -- RSM-11: the age of the stop episode: consecutive    *)
(*                    cycles ending with the ramp-down request output on, *)
(*                    whatever the speed read (capped at MaxStopCycles+2);*)
(*                    1 again when a cycle reads standstill and accepts a *)
(*                    command (a new trigger at standstill).              *)
(*   last_accepted -- the kind of command the last cycle accepted, "NONE".*)
(*   jog_in_auto   -- RSM-08: the last cycle popped JOG_START/JOG_STOP    *)
(*                    with selector AUTO or session AUTO.                 *)
(*   obs_guard_fault  -- RSM-05/06: the last cycle accepted a RESET or    *)
(*                    SERVO_ON whose cycle read drive_fault.              *)
(*   obs_servo_on_powered -- RSM-06: the last cycle accepted a SERVO_ON   *)
(*                    while the outputs were powered.                     *)
(*   obs_t2        -- RSM-06: a T2_CONFIRM was accepted and the selector  *)
(*                    stayed on T2, unpowered, without E-stop demand.     *)
(*   obs_drive_fault -- RSM-07: the last cycle read drive_fault with the  *)
(*                    outputs powered at its start.                      *)
(*   obs_fieldbus_lost -- seed/RSM-03: a cycle read fieldbus_ok = FALSE.  *)
(*   obs_link_lost -- RSM-13/seed (issue 16): the last cycle read the     *)
(*                    operator link lost with a jog speed commanded at    *)
(*                    its start.                                          *)
(*   obs_unexpected_motion -- RSM-11 (standstill monitoring): the last    *)
(*                    cycle read speed # ZERO with power on and no motion  *)
(*                    commanded at its start.                              *)
(*   t1_overspeed  -- RSM-10: the last cycle read OVER_T1 or OVER_T2      *)
(*                    while the session output (at its start) was T1.     *)
(*   obs_t2_overspeed -- UCA-RSM-12: the last cycle read OVER_T2 while    *)
(*                    the session output (at its start) was T2.           *)
(*   obs_fb_contactor, obs_fb_brake -- UCA-RSM-13: consecutive cycles     *)
(*                    whose feedback read disagreed with the output at    *)
(*                    the cycle's start (contactor, brake release), 1     *)
(*                    again when that output changed since the previous  *)
(*                    cycle; latched at FeedbackCycles + 1 (a disagreement *)
(*                    under one command lasted that long: was read).      *)
(*   obs_was_released -- the brake release output at the start of the    *)
(*                    last cycle (obs_was_enabled is the contactor's).    *)
(*   obs_booted, obs_self_test_failed -- RSM-12: the first cycle read     *)
(*                    self_test_ok = FALSE.                               *)
(*   obs_arming    -- RSM-07/RSM-15: consecutive cycles that read        *)
(*                    servo_ready FALSE and end with drive enable on      *)
(*                    (capped at ArmingTimeout + 2).                      *)
(*   obs_was_enabled -- UCA-RSM-02: drive enable was on at the start of   *)
(*                    the last cycle.                                      *)
(*   obs_ready_lost -- UCA-RSM-03: the last cycle read servo_ready FALSE  *)
(*                    with the brakes released at its start.              *)
(*   obs_panic     -- UCA-RSM-05 (ISO 10218-1 5.8.3): a cycle read either *)
(*                    enabling channel in PANIC and none since read both  *)
(*                    RELEASED.                                           *)
(*   obs_jog_axis  -- UCA-RSM-14: the axis of the JOG_START last accepted *)
(*                    (0 once that jog is over: a JOG_STOP accepted, a    *)
(*                    Cat 1 stop shown or every power output off; a Cat 2 *)
(*                    pause keeps it for the Resume).                     *)
(*   obs_ramp_cut  -- UCA-RSM-16: if the last cycle began with the        *)
(*                    ramp-down request on and ended with a power output  *)
(*                    off, the session output at its start and the speed  *)
(*                    it read (the speed is a free signal, outside the    *)
(*                    View); else NoCut, also after a Submit (the cycle's *)
(*                    own state is the one checked).                      *)
(*   obs_popped    -- RSM-13: the last event was a cycle that began with  *)
(*                    a command queued (queue_length > 0).                *)
(*   obs_submit_lost -- RSM-14: the last event was a Submit that neither  *)
(*                    grew queue_length by one (queue not full) nor was   *)
(*                    rejected at once with QUEUE_FULL (queue full).      *)
VARIABLES obs_estop, obs_open_a, obs_open_b, obs_disagree, obs_locked, obs_ramp,
          last_accepted, jog_in_auto, obs_guard_fault, obs_servo_on_powered, obs_t2,
          obs_drive_fault, obs_fieldbus_lost, obs_unexpected_motion, t1_overspeed,
          obs_booted, obs_self_test_failed,
          obs_arming, obs_popped, obs_submit_lost, obs_link_lost,
          obs_was_enabled, obs_ready_lost, obs_panic, obs_t2_overspeed,
          obs_fb_contactor, obs_fb_brake, obs_was_released, obs_jog_axis, obs_ramp_cut

mgrVars  == <<state, selector, session_mode, stop_category, fault_code,
              last_reject_reason, command_result, estop_mismatch,
              safeguard_mismatch, enabling_mismatch, selector_invalid,
              state_cycles, t2_confirmed, resume_to, jog, queue, axes,
              stale_commands, estop_tested_a, estop_tested_b, enable_release_required,
              contactor_fb_cycles, brake_fb_cycles, contactor_fb_cmd, brake_fb_cmd>>
obsVars  == <<obs_estop, obs_open_a, obs_open_b, obs_disagree, obs_locked, obs_ramp,
              last_accepted, jog_in_auto, obs_guard_fault, obs_servo_on_powered, obs_t2,
              obs_drive_fault, obs_fieldbus_lost, obs_unexpected_motion, t1_overspeed,
              obs_booted, obs_self_test_failed,
              obs_arming, obs_popped, obs_submit_lost, obs_link_lost,
              obs_was_enabled, obs_ready_lost, obs_panic, obs_t2_overspeed,
              obs_fb_contactor, obs_fb_brake, obs_was_released, obs_jog_axis,
              obs_ramp_cut>>
histVars == <<inputs, obsVars>>
vars     == <<mgrVars, histVars, event>>

\* The held input signals (see the environment below).
Held(in) == <<in.estop_a, in.estop_b, in.gate_a, in.gate_b, in.enable_a, in.enable_b,
              in.selector>>

\* The manager state as one record, so that the sections can be composed.
Mgr == [state |-> state, selector |-> selector, session_mode |-> session_mode,
        stop_category |-> stop_category, fault_code |-> fault_code,
        last_reject_reason |-> last_reject_reason, command_result |-> command_result,
        estop_mismatch |-> estop_mismatch, safeguard_mismatch |-> safeguard_mismatch,
        enabling_mismatch |-> enabling_mismatch, selector_invalid |-> selector_invalid,
        state_cycles |-> state_cycles, t2_confirmed |-> t2_confirmed,
        resume_to |-> resume_to, jog |-> jog, queue |-> queue, axes |-> axes,
        stale_commands |-> stale_commands, estop_tested_a |-> estop_tested_a,
        estop_tested_b |-> estop_tested_b,
        enable_release_required |-> enable_release_required,
        contactor_fb_cycles |-> contactor_fb_cycles, brake_fb_cycles |-> brake_fb_cycles,
        contactor_fb_cmd |-> contactor_fb_cmd, brake_fb_cmd |-> brake_fb_cmd]

SetMgr(m) ==
    /\ state' = m.state                 /\ selector' = m.selector
    /\ session_mode' = m.session_mode   /\ stop_category' = m.stop_category
    /\ fault_code' = m.fault_code       /\ last_reject_reason' = m.last_reject_reason
    /\ command_result' = m.command_result
    /\ estop_mismatch' = m.estop_mismatch
    /\ safeguard_mismatch' = m.safeguard_mismatch
    /\ enabling_mismatch' = m.enabling_mismatch
    /\ selector_invalid' = m.selector_invalid
    /\ state_cycles' = m.state_cycles   /\ t2_confirmed' = m.t2_confirmed
    /\ resume_to' = m.resume_to         /\ jog' = m.jog
    /\ stale_commands' = m.stale_commands
    /\ estop_tested_a' = m.estop_tested_a /\ estop_tested_b' = m.estop_tested_b
    /\ enable_release_required' = m.enable_release_required
    /\ contactor_fb_cycles' = m.contactor_fb_cycles /\ brake_fb_cycles' = m.brake_fb_cycles
    /\ contactor_fb_cmd' = m.contactor_fb_cmd /\ brake_fb_cmd' = m.brake_fb_cmd
    /\ queue' = m.queue                 /\ axes' = m.axes

-----------------------------------------------------------------------------
(*********************** Derived input facts (§2) **************************)
EstopTripped(in) == ~in.estop_a \/ ~in.estop_b                    \* 1oo2, RSM-04
GateOpen(in)     == ~in.gate_a \/ ~in.gate_b                      \* 1oo2, RSM-04
EnableMiddle(in) == in.enable_a = "MIDDLE" /\ in.enable_b = "MIDDLE"
EnablePanic(in)  == in.enable_a = "PANIC" \/ in.enable_b = "PANIC"
EnableReleased(in) == in.enable_a = "RELEASED" /\ in.enable_b = "RELEASED"

Manual(m) == m.session_mode \in {"T1", "T2"}

\* "in AUTO" of §6.
InAuto(m) == m.selector = "AUTO" \/ m.session_mode = "AUTO"

-----------------------------------------------------------------------------
(******************** State entry and per-state data (§4) ******************)
\* Entering a state sets its data afresh; callers then set what the row keeps.
Enter(m, s) ==
    [m EXCEPT !.state        = s,
              !.session_mode = IF s \in Powered THEN m.session_mode ELSE "NONE",
              !.t2_confirmed = FALSE,
              !.state_cycles = 0,
              !.resume_to    = "NONE",
              !.jog          = NoJog,
              !.fault_code   = "NONE"]

\* "-> X, CATn": set the status field stop_category (§5, §7).
WithCat(m, cat) == [m EXCEPT !.stop_category = cat]

Lockout(m, code) == [Enter(m, "ERROR_LOCKOUT") EXCEPT !.fault_code = code,
                                                      !.stop_category = "CAT0"]

-----------------------------------------------------------------------------
(************************ §3 Channel monitoring ****************************)
\* mismatch := (a != b) ? min(mismatch + 1, D + 1) : 0   (every state)
Count(n, bad) == IF bad THEN Min(n + 1, D + 1) ELSE 0

Monitor(m, in) ==
    [m EXCEPT !.estop_mismatch     = Count(@, in.estop_a # in.estop_b),
              !.safeguard_mismatch = Count(@, in.gate_a # in.gate_b),
              !.enabling_mismatch  = Count(@, in.enable_a # in.enable_b),
              !.selector_invalid   = Count(@, in.selector = "INVALID"),
              !.selector           = in.selector,
              \* K37: an E-stop channel seen open (tripped) since the last Reset
              !.estop_tested_a     = @ \/ ~in.estop_a,
              !.estop_tested_b     = @ \/ ~in.estop_b,
              \* K39 (ISO 10218-1 5.8.3): from PANIC only RELEASED re-arms the
              \* enabling device; PANIC -> MIDDLE does not enable
              !.enable_release_required = EnablePanic(in) \/ (@ /\ ~EnableReleased(in))]

\* A counter above D is a discrepancy fault; codes in the order of §3.
DiscrepancyCode(m) ==
    IF      m.estop_mismatch     > D THEN "DISCREPANCY_ESTOP"
    ELSE IF m.safeguard_mismatch > D THEN "DISCREPANCY_SAFEGUARD"
    ELSE IF m.enabling_mismatch  > D THEN "DISCREPANCY_ENABLING"
    ELSE IF m.selector_invalid   > D THEN "SELECTOR_INVALID"
    ELSE "NONE"

-----------------------------------------------------------------------------
(************ §5 Safety evaluation: one guard and one effect per row ********)
(* `m` is the manager after §3 (its state is the state before the row).  *)
\* "powered, not (STOPPING with CAT1, or with its timer expired and the arm
\* still moving)" (C12-C14): an expired stop timer is C20's (Cat 0), not an
\* escalation.
StopCat1Free(m, in) ==
    /\ m.state \in Powered
    /\ ~(/\ m.state = "STOPPING"
         /\ \/ m.stop_category = "CAT1"
            \/ m.state_cycles = MaxStopCycles /\ in.speed # "ZERO")

C01_Guard(m, in) == m.state = "ERROR_LOCKOUT"                   \* RSM-04
C02_Guard(m, in) == m.state = "BOOT" /\ ~in.self_test_ok        \* RSM-12
C03_Guard(m, in) == DiscrepancyCode(m) # "NONE"                 \* RSM-04, RSM-02
C24_Guard(m, in) == ~in.fieldbus_ok                             \* seed, RSM-03
\* C30 (issue 29 item 10): a contactor or brake feedback that disagreed with
\* its command for more than FeedbackCycles cycles (FeedbackMonitor below).
FeedbackCode(m) ==
    IF      m.contactor_fb_cycles > FeedbackCycles THEN "CONTACTOR_FEEDBACK"
    ELSE IF m.brake_fb_cycles > FeedbackCycles     THEN "BRAKE_FEEDBACK"
    ELSE "NONE"
C30_Guard(m, in) == FeedbackCode(m) # "NONE"                    \* RSM-03, RSM-07
C04_Guard(m, in) == m.state = "BOOT" /\ EstopTripped(in)        \* RSM-12
C05_Guard(m, in) == m.state = "BOOT"                            \* RSM-12
C06_Guard(m, in) == m.state # "ESTOP_ACTIVE" /\ EstopTripped(in) \* RSM-05
C07_Guard(m, in) == m.state = "ESTOP_ACTIVE" /\ ~EstopTripped(in) \* RSM-05
C08_Guard(m, in) == m.state = "ESTOP_ACTIVE"                    \* RSM-05
C09_Guard(m, in) == m.state \in Powered /\ in.drive_fault       \* RSM-07, RSM-03
C10_Guard(m, in) == /\ m.state \in Powered /\ m.session_mode = "T1"  \* RSM-10
                    /\ in.speed \in {"OVER_T1", "OVER_T2"}
\* C29 (issue 29 item 5): measured TCP speed above the T2 limit in a T2 session.
C29_Guard(m, in) == /\ m.state \in Powered /\ m.session_mode = "T2"  \* RSM-10, RSM-03
                    /\ in.speed = "OVER_T2"
\* C25: standstill monitoring where power is on and no motion is commanded
\* (no exemption: every stop, a JOG_STOP's too, ends in these states only
\* after a cycle that measured standstill, C18/C19/C28).
C25_Guard(m, in) == /\ m.state \in {"ARMING", "AUTO_IDLE", "MANUAL_IDLE", "HOLD"}
                    /\ in.speed # "ZERO"                          \* RSM-11, RSM-03
\* C27 (issue 29 item 3): a drive that stops reporting ready once the brakes
\* are released can no longer hold the axis: Cat 0 and a lockout.
ReadyStates == Powered \ {"ARMING"}
C27_Guard(m, in) == m.state \in ReadyStates /\ ~in.servo_ready  \* RSM-07, RSM-03
C11_Guard(m, in) == m.state \in Powered /\ Manual(m) /\ EnablePanic(in)  \* RSM-09
C12_Guard(m, in) == StopCat1Free(m, in) /\ in.selector # m.session_mode      \* RSM-02
C13_Guard(m, in) == StopCat1Free(m, in) /\ m.session_mode = "AUTO" /\ GateOpen(in) \* RSM-08
C14_Guard(m, in) == StopCat1Free(m, in) /\ Manual(m) /\ ~EnableMiddle(in)    \* RSM-09
\* issue 16: the controlling operator client's heartbeat expired (link lost,
\* client hung or socket closed) while jogging: a Cat 2 stop, as a Pause.
C26_Guard(m, in) == m.state = "MANUAL_JOGGING" /\ ~in.operator_link_ok     \* RSM-13, seed
C15_Guard(m, in) == m.state = "ARMING" /\ in.servo_ready                 \* RSM-07
C16_Guard(m, in) == m.state = "ARMING" /\ m.state_cycles = ArmingTimeoutCycles
C17_Guard(m, in) == m.state = "ARMING"                                   \* RSM-07
C18_Guard(m, in) == /\ m.state = "STOPPING" /\ in.speed = "ZERO"         \* RSM-11
                    /\ m.stop_category = "CAT1"
C19_Guard(m, in) == /\ m.state = "STOPPING" /\ in.speed = "ZERO"         \* RSM-11
                    /\ m.stop_category = "CAT2"
\* C28 (issue 29 item 1): a JOG_STOP's Cat 2 stop (no resume target) ends in
\* MANUAL_IDLE once the arm is measured at standstill.
C28_Guard(m, in) == /\ m.state = "STOPPING" /\ in.speed = "ZERO"         \* RSM-09, RSM-11
                    /\ m.stop_category = "CAT2" /\ m.resume_to = "NONE"
C20_Guard(m, in) == m.state = "STOPPING" /\ m.state_cycles = MaxStopCycles
C21_Guard(m, in) == m.state = "STOPPING"                                 \* RSM-11
C22_Guard(m, in) == m.state = "IDLE" /\ (in.selector # "T2" \/ m.t2_confirmed) \* RSM-06

C01(m, in) == m                                        \* stay: only re-init leaves
C02(m, in) == Lockout(m, "SELF_TEST_FAILED")
C03(m, in) == Lockout(m, DiscrepancyCode(m))
C24(m, in) == Lockout(m, "FIELDBUS_LOSS")
C30(m, in) == Lockout(m, FeedbackCode(m))
C04(m, in) == WithCat(Enter(m, "ESTOP_ACTIVE"), "CAT0")
C05(m, in) == Enter(m, "IDLE")
C06(m, in) == WithCat(Enter(m, "ESTOP_ACTIVE"), "CAT0")
\* never IDLE (RSM-05); the commands queued now were submitted before the
\* release: a RESET among them is stale (K36).
C07(m, in) == [Enter(m, "ESTOP_RESET_NEEDED") EXCEPT !.stale_commands = Len(m.queue)]
C08(m, in) == m
C09(m, in) == Lockout(m, "DRIVE_FAULT")
C10(m, in) == Lockout(m, "T1_OVERSPEED")
C29(m, in) == Lockout(m, "T2_OVERSPEED")
C25(m, in) == Lockout(m, "STANDSTILL_VIOLATION")
C27(m, in) == Lockout(m, "SERVO_READY_LOST")
C11(m, in) == WithCat(Enter(m, "IDLE"), "CAT0")
\* A Cat 1 stop; escalating a stop in progress (STOPPING CAT2) keeps its
\* timer and counts the cycle (as C21, at most up to the limit): the stop
\* watchdog runs from the first trigger of the episode.
\* From ARMING (brakes engaged, drives not yet ready: nothing can move) the
\* Cat 1 stop is complete at once: power is removed (IDLE), issue 29 item 2.
StopCat1(m) == IF m.state = "ARMING" THEN WithCat(Enter(m, "IDLE"), "CAT1")
               ELSE [WithCat(Enter(m, "STOPPING"), "CAT1")
                       EXCEPT !.state_cycles = IF m.state = "STOPPING"
                                               THEN Min(m.state_cycles + 1, MaxStopCycles)
                                               ELSE 0]
C12(m, in) == StopCat1(m)
C13(m, in) == StopCat1(m)
C14(m, in) == StopCat1(m)
C26(m, in) == [WithCat(Enter(m, "STOPPING"), "CAT2")
                 EXCEPT !.resume_to = "MANUAL_JOGGING", !.jog = m.jog]
C15(m, in) == Enter(m, IF m.session_mode = "AUTO" THEN "AUTO_IDLE" ELSE "MANUAL_IDLE")
C16(m, in) == Lockout(m, "ARMING_TIMEOUT")
C17(m, in) == [m EXCEPT !.state_cycles = @ + 1]
C18(m, in) == Enter(m, "IDLE")                         \* power removed, brakes on
C28(m, in) == Enter(m, "MANUAL_IDLE")
C19(m, in) == [Enter(m, "HOLD") EXCEPT !.resume_to = m.resume_to, !.jog = m.jog]
C20(m, in) == Lockout(m, "STOP_TIMEOUT")
C21(m, in) == [m EXCEPT !.state_cycles = @ + 1]
\* Off T2, or confirmed T2ConfirmTimeoutCycles cycles ago: cleared; else it
\* ages (issue 29 item 5: the confirmation expires).
C22(m, in) == IF in.selector # "T2" \/ m.state_cycles = T2ConfirmTimeoutCycles
              THEN [m EXCEPT !.t2_confirmed = FALSE, !.state_cycles = 0]
              ELSE [m EXCEPT !.state_cycles = @ + 1]
C23(m, in) == m                                        \* no change

\* First matching row wins (§5). The chain is written once, here.  The
\* latching rows C09, C27, C10, C29, C25 precede the E-stop's C06 (issue 29
\* item 7): an E-stop in the same cycle must not make the fault forgotten.
SafetyRow(m, in) ==
    IF      C01_Guard(m, in) THEN "C01"
    ELSE IF C02_Guard(m, in) THEN "C02"
    ELSE IF C03_Guard(m, in) THEN "C03"
    ELSE IF C24_Guard(m, in) THEN "C24"
    ELSE IF C30_Guard(m, in) THEN "C30"
    ELSE IF C04_Guard(m, in) THEN "C04"
    ELSE IF C05_Guard(m, in) THEN "C05"
    ELSE IF C09_Guard(m, in) THEN "C09"
    ELSE IF C27_Guard(m, in) THEN "C27"
    ELSE IF C10_Guard(m, in) THEN "C10"
    ELSE IF C29_Guard(m, in) THEN "C29"
    ELSE IF C25_Guard(m, in) THEN "C25"
    ELSE IF C06_Guard(m, in) THEN "C06"
    ELSE IF C07_Guard(m, in) THEN "C07"
    ELSE IF C08_Guard(m, in) THEN "C08"
    ELSE IF C11_Guard(m, in) THEN "C11"
    ELSE IF C12_Guard(m, in) THEN "C12"
    ELSE IF C13_Guard(m, in) THEN "C13"
    ELSE IF C14_Guard(m, in) THEN "C14"
    ELSE IF C26_Guard(m, in) THEN "C26"
    ELSE IF C15_Guard(m, in) THEN "C15"
    ELSE IF C16_Guard(m, in) THEN "C16"
    ELSE IF C17_Guard(m, in) THEN "C17"
    ELSE IF C18_Guard(m, in) THEN "C18"
    ELSE IF C28_Guard(m, in) THEN "C28"
    ELSE IF C19_Guard(m, in) THEN "C19"
    ELSE IF C20_Guard(m, in) THEN "C20"
    ELSE IF C21_Guard(m, in) THEN "C21"
    ELSE IF C22_Guard(m, in) THEN "C22"
    ELSE "C23"

Safety(m, in) ==
    LET r == SafetyRow(m, in) IN
    CASE r = "C01" -> C01(m, in) [] r = "C02" -> C02(m, in)
      [] r = "C03" -> C03(m, in) [] r = "C04" -> C04(m, in)
      [] r = "C05" -> C05(m, in) [] r = "C06" -> C06(m, in)
      [] r = "C07" -> C07(m, in) [] r = "C08" -> C08(m, in)
      [] r = "C09" -> C09(m, in) [] r = "C10" -> C10(m, in)
      [] r = "C11" -> C11(m, in) [] r = "C12" -> C12(m, in)
      [] r = "C13" -> C13(m, in) [] r = "C14" -> C14(m, in)
      [] r = "C15" -> C15(m, in) [] r = "C16" -> C16(m, in)
      [] r = "C17" -> C17(m, in) [] r = "C18" -> C18(m, in)
      [] r = "C19" -> C19(m, in) [] r = "C20" -> C20(m, in)
      [] r = "C21" -> C21(m, in) [] r = "C22" -> C22(m, in)
      [] r = "C23" -> C23(m, in) [] r = "C24" -> C24(m, in)
      [] r = "C25" -> C25(m, in) [] r = "C26" -> C26(m, in)
      [] r = "C27" -> C27(m, in) [] r = "C28" -> C28(m, in)
      [] r = "C29" -> C29(m, in) [] r = "C30" -> C30(m, in)

-----------------------------------------------------------------------------
(********** §6 One command from the queue: validation rows K01-K35 *********)
(* `m` is the manager after §5; `c` the popped command; `in` the inputs.  *)
ValidJog(c) == c.axis \in Axes /\ c.direction \in {-1, 1} /\ c.speed_mm_s > 0
               /\ c.speed_mm_s <= T2SpeedLimit  \* issue 29 item 5: no jog request above T2's limit

CommandRow(m, c, in) ==
    IF m.state = "ERROR_LOCKOUT" THEN "K01"                            \* RSM-04
    ELSE CASE
      c.kind = "RESET" ->                                             \* RSM-05
        IF      m.state = "ESTOP_ACTIVE"        THEN "K02"
        ELSE IF m.stale_commands > 0            THEN "K36"   \* issued before release
        ELSE IF m.state # "ESTOP_RESET_NEEDED"  THEN "K03"
        ELSE IF in.drive_fault                  THEN "K04"
        ELSE IF ~(m.estop_tested_a /\ m.estop_tested_b) THEN "K37"  \* channel test
        ELSE "K05"
   [] c.kind = "SERVO_ON" ->                                          \* RSM-06
        \* K38: IDLE before §5 too (`state` is the state at the cycle start): a
        \* Servo-on popped in the cycle whose §5 row removed power (C11, C18)
        \* would keep the contactor closed across the stop.
        IF      m.state # "IDLE"                                  THEN "K06"
        ELSE IF state # "IDLE"                                    THEN "K38"
        ELSE IF in.drive_fault                                    THEN "K07"
        ELSE IF m.selector = "INVALID"                            THEN "K08"
        ELSE IF m.selector = "AUTO" /\ GateOpen(in)               THEN "K09"
        ELSE IF m.selector \in {"T1", "T2"} /\ ~EnableMiddle(in)  THEN "K10"
        \* K39: MIDDLE reached from PANIC without RELEASED (ISO 10218-1 5.8.3)
        ELSE IF m.selector \in {"T1", "T2"} /\ m.enable_release_required THEN "K39"
        ELSE IF m.selector = "T2" /\ ~m.t2_confirmed              THEN "K11"
        ELSE "K12"
   [] c.kind = "SERVO_OFF" ->                                         \* RSM-13, RSM-11
        IF m.state \notin {"ARMING", "HOLD"} \cup Operational THEN "K13" ELSE "K14"
   [] c.kind = "START" ->                                             \* RSM-08
        IF      m.state \in {"MANUAL_IDLE", "MANUAL_JOGGING"} THEN "K15"
        ELSE IF m.state # "AUTO_IDLE"                         THEN "K16"
        ELSE IF GateOpen(in)                                  THEN "K17"
        ELSE "K18"
   [] c.kind = "PAUSE" ->                                             \* RSM-11
        IF m.state \notin Motion THEN "K19" ELSE "K20"
   [] c.kind = "RESUME" ->                                            \* RSM-11
        IF      m.state # "HOLD"                                    THEN "K21"
        ELSE IF m.resume_to = "AUTO_RUNNING" /\ GateOpen(in)        THEN "K22"
        ELSE IF m.resume_to = "MANUAL_JOGGING" /\ ~EnableMiddle(in) THEN "K23"
        ELSE "K24"
   [] c.kind = "JOG_START" ->                                         \* RSM-08/09/10
        IF      InAuto(m)                 THEN "K25"
        ELSE IF ~ValidJog(c)              THEN "K26"
        ELSE IF m.state # "MANUAL_IDLE"   THEN "K27"
        ELSE IF ~EnableMiddle(in)         THEN "K28"
        ELSE "K29"
   [] c.kind = "JOG_STOP" ->                                          \* RSM-08/09
        IF      InAuto(m)                   THEN "K30"
        ELSE IF m.state # "MANUAL_JOGGING"  THEN "K31"
        ELSE "K32"
   [] c.kind = "T2_CONFIRM" ->                                        \* RSM-06
        IF      m.state # "IDLE"       THEN "K33"
        ELSE IF m.selector # "T2"      THEN "K34"
        ELSE "K35"

\* The reject rows and their reason codes (RSM-13).
RejectReason ==
    [K01 |-> "LOCKED_OUT",    K02 |-> "ESTOP_PRESSED",    K03 |-> "WRONG_STATE",
     K04 |-> "DRIVE_FAULT",   K36 |-> "ESTOP_PRESSED",    K37 |-> "CHANNEL_TEST_PENDING",
     K06 |-> "WRONG_STATE",   K38 |-> "WRONG_STATE",      K07 |-> "DRIVE_FAULT",
     K08 |-> "SELECTOR_INVALID", K09 |-> "SAFEGUARD_OPEN",
     K10 |-> "ENABLE_NOT_MIDDLE", K39 |-> "ENABLE_NOT_MIDDLE", K11 |-> "T2_NOT_CONFIRMED",
     K13 |-> "WRONG_STATE",   K15 |-> "WRONG_MODE",       K16 |-> "WRONG_STATE",
     K17 |-> "SAFEGUARD_OPEN", K19 |-> "WRONG_STATE",     K21 |-> "WRONG_STATE",
     K22 |-> "SAFEGUARD_OPEN", K23 |-> "ENABLE_NOT_MIDDLE",
     K25 |-> "JOG_IN_AUTO",   K26 |-> "INVALID_ARGUMENT", K27 |-> "WRONG_STATE",
     K28 |-> "ENABLE_NOT_MIDDLE", K30 |-> "JOG_IN_AUTO",  K31 |-> "WRONG_STATE",
     K33 |-> "WRONG_STATE",   K34 |-> "WRONG_MODE"]

RejectRows == DOMAIN RejectReason

\* A rejected command changes nothing but the two reason fields (RSM-13).
Reject(m, reason) == [m EXCEPT !.command_result = reason,
                               !.last_reject_reason = reason]

\* The accepting rows.
K05(m, c, in) == [Enter(m, "IDLE") EXCEPT !.estop_tested_a = FALSE,     \* INV-RESET
                                          !.estop_tested_b = FALSE]
K12(m, c, in) == [Enter(m, "ARMING") EXCEPT !.session_mode = m.selector,
                                            !.stop_category = "NONE"]
K14(m, c, in) == WithCat(Enter(m, IF m.state = "ARMING" THEN "IDLE" ELSE "STOPPING"), "CAT1")
K18(m, c, in) == Enter(m, "AUTO_RUNNING")
K20(m, c, in) == [WithCat(Enter(m, "STOPPING"), "CAT2")
                    EXCEPT !.resume_to = m.state, !.jog = m.jog]
K24(m, c, in) == [Enter(m, m.resume_to) EXCEPT !.jog = m.jog]
ClampT1(m, v) == IF m.session_mode = "T1" THEN Min(v, T1SpeedLimit) ELSE v  \* RSM-10
K29(m, c, in) == [Enter(m, "MANUAL_JOGGING")
                    EXCEPT !.jog = [axis |-> c.axis, direction |-> c.direction,
                                    speed_mm_s |-> ClampT1(m, c.speed_mm_s)]]
\* issue 29 item 1: a JOG_STOP is a Cat 2 stop (IEC 60204-1 9.2.2), ramped
\* down and watched by the stop timer (C20); C28 ends it in MANUAL_IDLE.
K32(m, c, in) == WithCat(Enter(m, "STOPPING"), "CAT2")
K35(m, c, in) == [m EXCEPT !.t2_confirmed = TRUE, !.state_cycles = 0]

Accept(r, m, c, in) ==
    LET n == CASE r = "K05" -> K05(m, c, in) [] r = "K12" -> K12(m, c, in)
               [] r = "K14" -> K14(m, c, in) [] r = "K18" -> K18(m, c, in)
               [] r = "K20" -> K20(m, c, in) [] r = "K24" -> K24(m, c, in)
               [] r = "K29" -> K29(m, c, in) [] r = "K32" -> K32(m, c, in)
               [] r = "K35" -> K35(m, c, in)
    IN [n EXCEPT !.command_result = "ACCEPTED"]

\* Pops at most one command (RSM-15); an empty queue sets command_result NONE.
CommandStep(m, in) ==
    IF m.queue = << >> THEN [m EXCEPT !.command_result = "NONE"]
    ELSE LET c  == Head(m.queue)
             m1 == [m EXCEPT !.queue = Tail(@)]
             r  == CommandRow(m1, c, in)
             m2 == IF r \in RejectRows THEN Reject(m1, RejectReason[r])
                                       ELSE Accept(r, m1, c, in)
         IN [m2 EXCEPT !.stale_commands = Max2(@ - 1, 0)]   \* K36: one fewer stale

-----------------------------------------------------------------------------
(******************** §8 PLCopen axes (RSM-17) *****************************)
(* Each axis steps by PLCopen!AxisStep (models/PLCopenAxisStep.tla; the  *)
(* model PLCopenAxis.tla checks it against the PLCopen legal transitions *)
(* for every current state, desired state and speed reading).            *)

\* The axis state the manager state wants (§8, first table).
DesiredAxis(m, i) ==
    IF m.state = "ERROR_LOCKOUT" /\ m.fault_code = "DRIVE_FAULT" THEN "ErrorStop"
    ELSE IF m.state \in {"AUTO_IDLE", "MANUAL_IDLE", "HOLD"} THEN "StandStill"
    ELSE IF m.state = "AUTO_RUNNING" THEN "SynchronizedMotion"
    ELSE IF m.state = "MANUAL_JOGGING" THEN
            (IF i = m.jog.axis THEN "ContinuousMotion" ELSE "StandStill")
    ELSE IF m.state = "STOPPING" THEN "Stopping"
    ELSE "Disabled"

AxesStep(m, in) ==
    [m EXCEPT !.axes = [i \in Axes |->
                 PLCopen!AxisStep(m.axes[i], DesiredAxis(m, i), in.speed = "ZERO")]]

-----------------------------------------------------------------------------
(************************ Outputs (§7, RSM-16) *****************************)
\* Each output as a function of a manager record: the requirement observers
\* read the outputs before and after a cycle.
ContactorOut(m)      == m.state \in Powered
DriveEnableOut(m)    == m.state \in Powered
\* issue 29 item 2: contactor and drive enable in ARMING, the brakes only
\* once the drives report ready (C15): contactor -> servo on -> brake release.
BrakeReleaseOut(m)   == m.state \in ReadyStates
RampDownOut(m)       == m.state = "STOPPING"
ResetLampOut(m)      == m.state = "ESTOP_RESET_NEEDED"
CommandedSpeedOut(m) == IF m.state = "MANUAL_JOGGING" THEN m.jog.speed_mm_s ELSE 0

\* Any of the three power outputs on.
PowerOut(m) == ContactorOut(m) \/ DriveEnableOut(m) \/ BrakeReleaseOut(m)

\* No motion commanded, over the outputs only: no jog speed, no ramp-down
\* request, no program running (the status record's state, RSM-16: an AUTO
\* program's path is commanded from the cycle Start is accepted) and no axis
\* output in a PLCopen motion state.  An axis left in Stopping without a
\* ramp-down request is not commanded motion (issue 29 item 1).
NoMotionOut(m) ==
    /\ CommandedSpeedOut(m) = 0 /\ ~RampDownOut(m) /\ m.state \notin Motion
    /\ \A i \in Axes : m.axes[i] \notin PLCopen!MotionStates

\* C30's monitoring (§3, every cycle, every state; C++ FeedbackMonitor): the
\* command is the output at the cycle's start (written by the previous cycle),
\* the feedback the input of this cycle. A disagreement counts; agreement
\* restarts the count; a command change during a disagreement restarts it at
\* 1 (the device gets its full switching time); above FeedbackCycles it latches.
FbCount(n, last, cmd, fb) ==
    IF n > FeedbackCycles THEN n
    ELSE IF cmd = fb THEN 0
    ELSE IF n > 0 /\ cmd # last THEN 1
    ELSE n + 1
FbLast(n, last, cmd, fb) ==
    IF n > FeedbackCycles THEN last ELSE IF cmd = fb THEN FALSE ELSE cmd

FeedbackMonitor(m, in) ==
    LET c == ContactorOut(m)
        b == BrakeReleaseOut(m)
    IN [m EXCEPT
          !.contactor_fb_cycles = FbCount(m.contactor_fb_cycles, m.contactor_fb_cmd, c, in.contactor_fb),
          !.contactor_fb_cmd    = FbLast(m.contactor_fb_cycles, m.contactor_fb_cmd, c, in.contactor_fb),
          !.brake_fb_cycles     = FbCount(m.brake_fb_cycles, m.brake_fb_cmd, b, in.brake_fb),
          !.brake_fb_cmd        = FbLast(m.brake_fb_cycles, m.brake_fb_cmd, b, in.brake_fb)]

\* §3 with the feedback monitoring: what the §5 rows read.
Monitored(in) == FeedbackMonitor(Monitor(Mgr, in), in)

(***************************** The two events (§1) *************************)
\* One scan cycle: §3, §5, §6 (against the state after §5), §8.
AfterSafety(in) == Safety(Monitored(in), in)
AfterCycle(in)  == AxesStep(CommandStep(AfterSafety(in), in), in)

\* Submit: a full queue rejects at once with QUEUE_FULL (RSM-14).
AfterSubmit(c) ==
    IF Len(queue) < QueueCapacity THEN [Mgr EXCEPT !.queue = Append(@, c)]
    ELSE [Mgr EXCEPT !.last_reject_reason = "QUEUE_FULL"]

\* The kind of the command the next cycle pops, "NONE" if the queue is empty.
Popped == IF queue = << >> THEN "NONE" ELSE Head(queue).kind

\* UCA-RSM-13's observer: consecutive cycles feedback # output at the start,
\* 1 again when the output changed since the previous cycle's start; latched
\* once it exceeds FeedbackCycles (UCA-RSM-15 reads it after the lockout).
ObsFb(o, prev, cmd, fb) ==
    IF o > FeedbackCycles THEN o        \* latched: the disagreement lasted
    ELSE IF fb = cmd THEN 0
    ELSE IF o > 0 /\ cmd # prev THEN 1
    ELSE Min(o + 1, FeedbackCycles + 1)

\* No ramped stop cut short by the last event (obs_ramp_cut).
NoCut == [session |-> "NONE", speed |-> "ZERO"]

Cycle(in) ==
    LET m2  == AfterSafety(in)
        m   == AxesStep(CommandStep(m2, in), in)     \* = AfterCycle(in)
        acc == IF m.command_result = "ACCEPTED" THEN Popped ELSE "NONE"
        tripped == EstopTripped(in)
        \* latched once a disagreement lasted D + 1 cycles (INV_DISCREPANCY: locked out)
        n(c, bad) == IF c > D THEN c ELSE IF bad THEN Min(c + 1, D + 1) ELSE 0
    IN /\ SetMgr(m)
       /\ inputs' = in
       /\ event' = [kind |-> "cycle", inputs |-> in]
       \* requirement observers (inputs, commands, outputs only)
       /\ obs_estop' = IF tripped THEN "DEMANDED"
                       ELSE IF obs_estop = "DEMANDED" THEN "RELEASED"
                       ELSE IF obs_estop = "RESET_ISSUED" /\ acc = "RESET" THEN "CLEAR"
                       ELSE obs_estop
       /\ obs_open_a' = ((obs_estop # "CLEAR" /\ obs_open_a) \/ ~in.estop_a)
       /\ obs_open_b' = ((obs_estop # "CLEAR" /\ obs_open_b) \/ ~in.estop_b)
       /\ obs_disagree' =
            [estop    |-> n(obs_disagree.estop, in.estop_a # in.estop_b),
             gate     |-> n(obs_disagree.gate, in.gate_a # in.gate_b),
             enable   |-> n(obs_disagree.enable, in.enable_a # in.enable_b),
             selector |-> n(obs_disagree.selector, in.selector \notin Modes)]
       /\ obs_locked' = (obs_locked \/ m.fault_code # "NONE")
       \* a cycle that reads standstill and accepts a command starts a new episode
       \* (a Servo-off after the Cat 2 stop reached HOLD in the same cycle)
       /\ obs_ramp' = IF ~RampDownOut(m) THEN 0
                      ELSE IF in.speed = "ZERO" /\ acc # "NONE" THEN 1
                      ELSE Min(obs_ramp + 1, MaxStopCycles + 2)
       /\ last_accepted' = acc
       /\ jog_in_auto' = /\ Popped \in {"JOG_START", "JOG_STOP"}
                         /\ (in.selector = "AUTO" \/ m.session_mode = "AUTO")
       /\ obs_guard_fault' = (acc \in {"RESET", "SERVO_ON"} /\ in.drive_fault)
       /\ obs_servo_on_powered' = (acc = "SERVO_ON" /\ PowerOut(Mgr))
       /\ obs_t2' = IF acc = "T2_CONFIRM" THEN 1
                    ELSE IF in.selector # "T2" \/ tripped \/ PowerOut(Mgr) \/ obs_t2 = 0 THEN 0
                    ELSE Min(obs_t2 + 1, T2ConfirmTimeoutCycles + 2)
       /\ obs_drive_fault' = (in.drive_fault /\ PowerOut(Mgr))
       /\ obs_fieldbus_lost' = (obs_fieldbus_lost \/ ~in.fieldbus_ok)
       /\ obs_unexpected_motion' =
            (PowerOut(Mgr) /\ NoMotionOut(Mgr) /\ in.speed # "ZERO")
       /\ t1_overspeed' = (session_mode = "T1" /\ in.speed \in {"OVER_T1", "OVER_T2"})
       /\ obs_t2_overspeed' = (session_mode = "T2" /\ in.speed = "OVER_T2")
       /\ obs_fb_contactor' = ObsFb(obs_fb_contactor, obs_was_enabled, ContactorOut(Mgr), in.contactor_fb)
       /\ obs_fb_brake' = ObsFb(obs_fb_brake, obs_was_released, BrakeReleaseOut(Mgr), in.brake_fb)
       /\ obs_was_released' = BrakeReleaseOut(Mgr)
       /\ obs_booted' = TRUE
       /\ obs_self_test_failed' = (obs_self_test_failed \/ (~obs_booted /\ ~in.self_test_ok))
       /\ obs_arming' = IF DriveEnableOut(m) /\ ~in.servo_ready
                        THEN Min(obs_arming + 1, ArmingTimeoutCycles + 2) ELSE 0
       /\ obs_was_enabled' = DriveEnableOut(Mgr)
       /\ obs_ready_lost' = (~in.servo_ready /\ BrakeReleaseOut(Mgr))
       /\ obs_panic' = (EnablePanic(in) \/ (obs_panic /\ ~EnableReleased(in)))
       /\ obs_popped' = (queue # << >>)
       /\ obs_submit_lost' = FALSE
       /\ obs_link_lost' = (~in.operator_link_ok /\ CommandedSpeedOut(Mgr) > 0)
       \* the jog the operator started: over with its JOG_STOP, a Cat 1 stop or
       \* power off; a Cat 2 pause (Pause, link loss) keeps it for the Resume
       /\ obs_jog_axis' = IF acc = "JOG_START" THEN Head(queue).axis
                          ELSE IF acc = "JOG_STOP" \/ ~PowerOut(m) \/ m.stop_category = "CAT1"
                          THEN 0 ELSE obs_jog_axis
       /\ obs_ramp_cut' = IF RampDownOut(Mgr) /\ ~(ContactorOut(m) /\ DriveEnableOut(m) /\ BrakeReleaseOut(m))
                          THEN [session |-> session_mode, speed |-> in.speed] ELSE NoCut

\* A RESET queued after the E-stop release is "issued after the release"
\* (RSM-05); the Submit's result (queued / queue_full) is its output.
Submit(c) ==
    /\ SetMgr(AfterSubmit(c))
    /\ event' = [kind |-> "submit", command |-> c]
    /\ obs_estop' = IF obs_estop = "RELEASED" /\ c.kind = "RESET" /\ Len(queue) < QueueCapacity
                    THEN "RESET_ISSUED" ELSE obs_estop
    /\ obs_popped' = FALSE
    /\ obs_ramp_cut' = NoCut
    \* RSM-14 over the outputs queue_length and last_reject_reason
    /\ obs_submit_lost' =
           ~IF Len(queue) < QueueCapacity THEN Len(queue') = Len(queue) + 1
            ELSE Len(queue') = Len(queue) /\ last_reject_reason' = "QUEUE_FULL"
    /\ UNCHANGED <<inputs, obs_open_a, obs_open_b, obs_disagree, obs_locked, obs_ramp,
                   last_accepted, jog_in_auto, obs_guard_fault, obs_servo_on_powered, obs_t2,
                   obs_drive_fault, obs_fieldbus_lost, obs_unexpected_motion, t1_overspeed,
                   obs_booted, obs_self_test_failed, obs_arming, obs_link_lost,
                   obs_was_enabled, obs_ready_lost, obs_panic, obs_t2_overspeed,
                   obs_fb_contactor, obs_fb_brake, obs_was_released, obs_jog_axis>>

-----------------------------------------------------------------------------
(************************** Environment and spec **************************)
(* The inputs of a cycle fall in two classes.                              *)
(*  - Held signals, the safety channels and the selector: the environment  *)
(*    keeps their levels and, per cycle, holds them all or changes one     *)
(*    group (the E-stop pair, the safeguard pair, the enabling pair, or   *)
(*    the selector).  Any input history is a sequence of such changes,    *)
(*    the manager seeing the intermediate vectors as extra cycles.         *)
(*  - Free signals, speed, servo_ready, drive_fault and self_test_ok:      *)
(*    chosen afresh each cycle from their allowed values where the coming  *)
(*    cycle reads them (page: speed only while powered -- C10, C18, C19,   *)
(*    the §8 Stopping axes and the T1 history; servo_ready only powered    *)
(*    -- C15, C27; drive_fault only while powered -- C09 -- or when a RESET or  *)
(*    SERVO_ON is at the head of the queue -- K04, K07; self_test_ok only *)
(*    in BOOT -- C02), and a fixed default (ZERO, FALSE, FALSE, TRUE)      *)
(*    elsewhere, where the value cannot change the successor.  Free        *)
(*    signals are therefore not part of the View.                          *)
(* With LockoutHoldsInputs (the CI cfg) the held signals stop changing     *)
(* once in ERROR_LOCKOUT: there, by C01 and K01, only the §3 counters and *)
(* the selector status still follow the inputs.  Cycles and Submits go on. *)
HeldVariants(cur) ==
    IF state = "ERROR_LOCKOUT" /\ LockoutHoldsInputs THEN {cur} ELSE
    {cur}
    \cup {[cur EXCEPT !.estop_a = p[1], !.estop_b = p[2]] : p \in EstopInputs}
    \cup {[cur EXCEPT !.gate_a = p[1], !.gate_b = p[2]] : p \in SafeguardInputs}
    \cup {[cur EXCEPT !.enable_a = p[1], !.enable_b = p[2]] : p \in EnablingInputs}
    \cup {[cur EXCEPT !.selector = v] : v \in SelectorInputs}

DriveFaultRead == \/ state \in Powered
                  \/ queue # << >> /\ Head(queue).kind \in {"RESET", "SERVO_ON"}

\* Every speed class in every powered state, whatever the session (issue 29:
\* an AUTO or T2 session may measure OVER_T1). Unpowered, nothing reads the
\* speed (§8 desires Disabled whatever it is; C25 and C10 are powered rows):
\* the design page (hazard analysis, environment) argues the abstraction.
SpeedChoices == IF state \notin Powered THEN {"ZERO"} ELSE SpeedInputs

FreeChoices ==
    [speed:        SpeedChoices,
     servo_ready:  IF state \in Powered THEN ServoReadyInputs ELSE {FALSE},
     drive_fault:  IF DriveFaultRead THEN DriveFaultInputs ELSE {FALSE},
     self_test_ok: IF state = "BOOT" THEN SelfTestInputs ELSE {TRUE}]

\* servo_ready holds its level once the drives are ready (C15) and a
\* held-change cycle keeps it; losing it is a free choice of its own.
FreeDefault == [speed |-> "ZERO", servo_ready |-> state \in ReadyStates,
                drive_fault |-> FALSE, self_test_ok |-> TRUE]

\* The feedback follows its command (the output at the cycle's start) unless a
\* FeedbackDisagree cycle says otherwise.
WithFree(h, f) == [h EXCEPT !.speed = f.speed, !.servo_ready = f.servo_ready,
                            !.drive_fault = f.drive_fault, !.self_test_ok = f.self_test_ok,
                            !.fieldbus_ok = TRUE, !.operator_link_ok = TRUE,
                            !.contactor_fb = ContactorOut(Mgr),
                            !.brake_fb = BrakeReleaseOut(Mgr)]

\* Fieldbus/cycle watchdog loss (C24) is a cycle of its own, the other free
\* signals at their defaults: C24 precedes every row that reads them but
\* C02, and lockout (C01) reads none of them.  Not offered in lockout.
FieldbusLoss(cur) ==
    IF state = "ERROR_LOCKOUT" \/ FALSE \notin FieldbusInputs THEN {}
    ELSE {[WithFree(cur, FreeDefault) EXCEPT !.fieldbus_ok = FALSE]}

\* Operator link loss (C26, issue 16) is a cycle of its own, the other free
\* signals at their defaults, offered only in MANUAL_JOGGING: no other row
\* reads operator_link_ok, so elsewhere it cannot change the successor.
LinkLoss(cur) ==
    IF state # "MANUAL_JOGGING" THEN {}
    ELSE {[WithFree(cur, FreeDefault) EXCEPT !.operator_link_ok = FALSE]}

\* A contactor or brake feedback that disagrees with its command (a welded or
\* not pulling-in contactor, a brake that stays applied or released) is a cycle
\* of its own, the other free signals at their defaults, in every state: the
\* counters are read by C30 only, which precedes every row that reads a free
\* signal but C02 (design page §13, the environment).  With
\* LockoutHoldsInputs the feedback, as the held signals, stops changing in
\* ERROR_LOCKOUT: C01 and K01 read no counter there and the fault is shown.
FeedbackDisagree(cur) ==
    IF ~FeedbackInputs \/ (state = "ERROR_LOCKOUT" /\ LockoutHoldsInputs) THEN {}
    ELSE {[WithFree(cur, FreeDefault) EXCEPT !.contactor_fb = ~ContactorOut(Mgr)],
          [WithFree(cur, FreeDefault) EXCEPT !.brake_fb = ~BrakeReleaseOut(Mgr)]}

\* An E-stop change together with any free choice (issue 29 item 7: an
\* E-stop pressed in the cycle that reads a drive fault, the drives not
\* ready, an overspeed or unexpected motion must not lose the lockout).
\* Offered also without CombineChanges: C06 competes with the latching
\* rows C09, C27, C10, C25 in the same cycle (design page, environment).
EstopWithFree(cur) ==
    IF state = "ERROR_LOCKOUT" /\ LockoutHoldsInputs THEN {}
    ELSE {WithFree([cur EXCEPT !.estop_a = p[1], !.estop_b = p[2]], f) :
              p \in EstopInputs, f \in FreeChoices}

\* With CombineChanges a cycle may change a held group and choose the free
\* signals at once; without it (the CI cfg) a cycle either changes one held
\* group (free signals at their defaults; the E-stop with any of them) or
\* holds them and chooses the free signals.
NextInputs(cur) ==
    IF CombineChanges
    THEN {WithFree(h, f) : h \in HeldVariants(cur), f \in FreeChoices}
         \cup FieldbusLoss(cur) \cup LinkLoss(cur) \cup FeedbackDisagree(cur)
    ELSE {WithFree(h, FreeDefault) : h \in HeldVariants(cur)} \cup EstopWithFree(cur)
         \cup {WithFree(cur, f) : f \in FreeChoices} \cup FieldbusLoss(cur) \cup LinkLoss(cur)
         \cup FeedbackDisagree(cur)

\* Before the first cycle (§7): BOOT, counters 0, selector INVALID, outputs
\* off, every axis Disabled.
Init ==
    /\ state = "BOOT"             /\ selector = "INVALID"
    /\ session_mode = "NONE"      /\ stop_category = "NONE"
    /\ fault_code = "NONE"        /\ last_reject_reason = "NONE"
    /\ command_result = "NONE"
    /\ estop_mismatch = 0 /\ safeguard_mismatch = 0
    /\ enabling_mismatch = 0 /\ selector_invalid = 0
    /\ state_cycles = 0           /\ t2_confirmed = FALSE
    /\ resume_to = "NONE"         /\ jog = NoJog
    /\ queue = << >>              /\ axes = [i \in Axes |-> "Disabled"]
    /\ inputs = InitialInputs     /\ event = [kind |-> "init"]
    /\ stale_commands = 0         /\ estop_tested_a = FALSE
    /\ estop_tested_b = FALSE
    /\ obs_estop = "CLEAR"        /\ obs_open_a = FALSE /\ obs_open_b = FALSE
    /\ obs_disagree = [estop |-> 0, gate |-> 0, enable |-> 0, selector |-> 0]
    /\ obs_locked = FALSE         /\ obs_ramp = 0
    /\ last_accepted = "NONE"     /\ jog_in_auto = FALSE
    /\ obs_guard_fault = FALSE    /\ obs_servo_on_powered = FALSE
    /\ obs_t2 = 0                 /\ obs_drive_fault = FALSE
    /\ obs_fieldbus_lost = FALSE  /\ obs_unexpected_motion = FALSE
    /\ t1_overspeed = FALSE       /\ obs_booted = FALSE
    /\ obs_self_test_failed = FALSE /\ obs_link_lost = FALSE
    /\ obs_arming = 0             /\ obs_popped = FALSE /\ obs_submit_lost = FALSE
    /\ obs_was_enabled = FALSE    /\ obs_ready_lost = FALSE /\ obs_panic = FALSE
    /\ obs_t2_overspeed = FALSE
    /\ contactor_fb_cycles = 0    /\ brake_fb_cycles = 0
    /\ contactor_fb_cmd = FALSE   /\ brake_fb_cmd = FALSE
    /\ obs_fb_contactor = 0       /\ obs_fb_brake = 0 /\ obs_was_released = FALSE
    /\ enable_release_required = FALSE
    /\ obs_jog_axis = 0
    /\ obs_ramp_cut = NoCut

\* A full queue rejects every command alike (QUEUE_FULL, only
\* last_reject_reason changes), so when it is full one representative
\* command is submitted: the other choices give the same View.
SubmitChoices == IF Len(queue) < QueueCapacity THEN Commands ELSE {Simple("RESET")}

Next ==
    \/ \E in \in NextInputs(inputs) : Cycle(in)
    \/ \E c \in SubmitChoices : Submit(c)

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(************************ Outputs (§7, RSM-16) *****************************)
contactor_closed     == ContactorOut(Mgr)
drive_enable         == DriveEnableOut(Mgr)
brake_release        == BrakeReleaseOut(Mgr)
ramp_down_request    == RampDownOut(Mgr)
reset_lamp           == ResetLampOut(Mgr)
commanded_speed_mm_s == CommandedSpeedOut(Mgr)
queue_length         == Len(queue)

(* The fingerprint.  It leaves out what no guard, no environment choice   *)
(* and no invariant reads, so that the quotient graph has the same        *)
(* behaviours for every checked property: `event` (how this state was     *)
(* reached), the free input signals of the last cycle (read by the       *)
(* invariants through observers, and directly by two: the View keeps the  *)
(* signal exactly where they read it -- a state is checked only when its   *)
(* View is new), and the write-only status field last_reject_reason.      *)
(* Traces still show them: TLC rebuilds a trace from real successor       *)
(* states.                                                                 *)
View == <<state, selector, session_mode, stop_category, fault_code,
          command_result, estop_mismatch, safeguard_mismatch,
          enabling_mismatch, selector_invalid, state_cycles, t2_confirmed,
          resume_to, jog, queue, axes, stale_commands, estop_tested_a, estop_tested_b,
          enable_release_required, contactor_fb_cycles, brake_fb_cycles,
          contactor_fb_cmd, brake_fb_cmd, Held(inputs), obsVars,
          IF brake_release THEN inputs.servo_ready ELSE FALSE,          \* UCA_BRAKE_ORDER
          IF obs_ramp > MaxStopCycles + 1 THEN inputs.speed ELSE "ZERO">>  \* RSM11_STOP_BUDGET

-----------------------------------------------------------------------------
(******************************* Invariants ********************************)
JogType == {NoJog} \cup [axis: Axes, direction: {-1, 1}, speed_mm_s: Nat \ {0}]

\* RSM-01: every variable in its type; the state one of the RSM-01 states, the
\* stop category of STOPPING 1 or 2, HOLD a category 2 pause.
TypeOK ==
    /\ state \in States
    /\ selector \in Selectors
    /\ session_mode \in Modes \cup {"NONE"}
    /\ stop_category \in StopCategories
    /\ fault_code \in FaultCodes
    /\ last_reject_reason \in Reasons \cup {"NONE"}
    /\ command_result \in Reasons \cup {"NONE", "ACCEPTED"}
    /\ estop_mismatch \in 0..(D + 1) /\ safeguard_mismatch \in 0..(D + 1)
    /\ enabling_mismatch \in 0..(D + 1) /\ selector_invalid \in 0..(D + 1)
    /\ state_cycles \in 0..Max2(Max2(ArmingTimeoutCycles, MaxStopCycles), T2ConfirmTimeoutCycles)
    /\ t2_confirmed \in BOOLEAN
    /\ resume_to \in {"NONE", "AUTO_RUNNING", "MANUAL_JOGGING"}
    /\ jog \in JogType
    /\ queue \in Seq(Commands) /\ Len(queue) <= QueueCapacity
    /\ axes \in [Axes -> PLCopen!AxisStates]
    /\ inputs \in Inputs
    /\ stale_commands \in 0..QueueCapacity
    /\ estop_tested_a \in BOOLEAN /\ estop_tested_b \in BOOLEAN
    /\ obs_estop \in {"CLEAR", "DEMANDED", "RELEASED", "RESET_ISSUED"}
    /\ obs_open_a \in BOOLEAN /\ obs_open_b \in BOOLEAN
    /\ obs_disagree \in [estop: 0..(D + 1), gate: 0..(D + 1), enable: 0..(D + 1),
                         selector: 0..(D + 1)]
    /\ obs_locked \in BOOLEAN /\ obs_ramp \in 0..(MaxStopCycles + 2)
    /\ last_accepted \in CommandKinds \cup {"NONE"}
    /\ jog_in_auto \in BOOLEAN /\ obs_guard_fault \in BOOLEAN
    /\ obs_servo_on_powered \in BOOLEAN /\ obs_t2 \in 0..(T2ConfirmTimeoutCycles + 2)
    /\ obs_drive_fault \in BOOLEAN /\ obs_fieldbus_lost \in BOOLEAN
    /\ obs_unexpected_motion \in BOOLEAN /\ t1_overspeed \in BOOLEAN
    /\ obs_booted \in BOOLEAN /\ obs_self_test_failed \in BOOLEAN
    /\ obs_arming \in 0..(ArmingTimeoutCycles + 2)
    /\ obs_was_enabled \in BOOLEAN /\ obs_ready_lost \in BOOLEAN /\ obs_panic \in BOOLEAN
    /\ obs_t2_overspeed \in BOOLEAN
    /\ contactor_fb_cycles \in 0..(FeedbackCycles + 1) /\ brake_fb_cycles \in 0..(FeedbackCycles + 1)
    /\ contactor_fb_cmd \in BOOLEAN /\ brake_fb_cmd \in BOOLEAN
    /\ obs_fb_contactor \in 0..(FeedbackCycles + 1) /\ obs_fb_brake \in 0..(FeedbackCycles + 1)
    /\ obs_was_released \in BOOLEAN
    /\ obs_jog_axis \in {0} \cup Axes
    /\ obs_ramp_cut \in [session: Modes \cup {"NONE"}, speed: Speeds]
    /\ enable_release_required \in BOOLEAN
    /\ obs_popped \in BOOLEAN /\ obs_submit_lost \in BOOLEAN
    /\ obs_link_lost \in BOOLEAN
    \* per-state data is meaningful only where §4 says so
    /\ (session_mode # "NONE") <=> (state \in Powered)
    /\ (fault_code # "NONE") <=> (state = "ERROR_LOCKOUT")
    /\ t2_confirmed => state = "IDLE"
    /\ state_cycles # 0 => state \in {"ARMING", "STOPPING"} \/ (state = "IDLE" /\ t2_confirmed)
    \* RSM-01: STOPPING is of category 1 or 2; HOLD is a category 2 pause
    /\ state = "STOPPING" => stop_category \in {"CAT1", "CAT2"}
    /\ state = "HOLD" => stop_category = "CAT2"
    /\ (resume_to # "NONE") => (state = "HOLD" \/ (state = "STOPPING" /\ stop_category = "CAT2"))
    /\ state = "HOLD" => resume_to # "NONE"
    /\ (jog # NoJog) <=> (state = "MANUAL_JOGGING" \/ resume_to = "MANUAL_JOGGING")

(***************************************************************************)
(* Requirement-level properties.  Written from REQUIREMENTS.md (RSM-xx)    *)
(* and the seed, over the INPUTS (`inputs`, the last cycle's) and the      *)
(* OUTPUTS (§7: power outputs, ramp-down request, reset lamp, commanded    *)
(* speed, axes, and the status record's session_mode, stop_category,       *)
(* fault_code, command_result), with the observers above as the only      *)
(* history.  None reads `state` or another model-internal variable.        *)
(* Each has a witness (Witness_<name>, the negation of its antecedent)    *)
(* that the checker must violate, and a killing mutant                     *)
(* (models/mutants/SystemStateManager.toml).                              *)
(***************************************************************************)
Unpowered == ~contactor_closed /\ ~drive_enable /\ ~brake_release
Locked    == fault_code # "NONE"                       \* status: a fault code shown
Cat1Ramp  == ramp_down_request /\ stop_category = "CAT1"

\* INV-RESET (RSM-05): after any E-stop demand on either channel, no power
\* output until a Reset command issued after both channels were seen
\* released was accepted.
INV_RESET == contactor_closed \/ drive_enable \/ brake_release => obs_estop = "CLEAR"

\* RSM-05: a Reset is accepted only when it was issued after the release
\* (not while the E-stop was pressed) and no drive fault was read.
RSM05_RESET_ACCEPTED == last_accepted = "RESET" => obs_estop = "CLEAR" /\ ~obs_guard_fault

\* RSM-04 (K37, test of both channels): a Reset is accepted only if both
\* E-stop channels were seen open (and, RSM-05, released) since the demand:
\* a one-channel demand leaves a stuck channel undetected otherwise.
RSM04_CHANNEL_TEST == last_accepted = "RESET" => obs_open_a /\ obs_open_b

\* INV-POWER (RSM-03, RSM-16): drive power only in ARMING, OPERATIONAL,
\* STOPPING and HOLD; in ESTOP_ACTIVE and ERROR_LOCKOUT the contactor is open
\* and the brakes engaged. Read from the status record and the outputs, not
\* from `state` (the outputs are defined from it, so that would be a
\* tautology): a fault code shown (ERROR_LOCKOUT) or an E-stop demand not yet
\* reset (ESTOP_ACTIVE / ESTOP_RESET_NEEDED) has every power output off.
INV_POWER == Locked \/ obs_estop # "CLEAR" => Unpowered

\* RSM-03/RSM-05: an E-stop demand on either channel removes drive power and
\* engages the brakes in the same cycle (Cat 0); every axis disabled.
RSM03_ESTOP_CAT0 ==
    ~inputs.estop_a \/ ~inputs.estop_b =>
        Unpowered /\ \A i \in Axes : axes[i] \in {"Disabled", "ErrorStop"}

\* INV-DISCREPANCY (RSM-04, RSM-02): channels that disagreed (or a selector
\* that read invalid) for more than D cycles in a row are locked out, and
\* the lockout is left by no input sequence (the inputs stay free in it).
INV_DISCREPANCY ==
    /\ (\/ obs_disagree.estop > D \/ obs_disagree.gate > D
        \/ obs_disagree.enable > D \/ obs_disagree.selector > D) => Locked /\ Unpowered
    /\ obs_locked => Locked /\ Unpowered /\ ~reset_lamp

\* Seed (loss of the EtherCAT fieldbus is a lockout cause), RSM-03 (a
\* hardware fault is a Cat 0 stop): after a fieldbus/cycle watchdog loss the
\* outputs are off and a fault code is shown.
RSM03_FIELDBUS == obs_fieldbus_lost => Locked /\ Unpowered

\* RSM-02: with drive power on, a selector reading other than the session's
\* mode (a change, or invalid) means a Cat 1 ramp-down.
RSM02_MODE_CHANGE == drive_enable /\ inputs.selector # session_mode => Cat1Ramp

\* INV-GATE (RSM-08): in AUTO (selector or session) with the safeguard open
\* on either channel, no drive is enabled except during a Cat 1 ramp (whose
\* end within the budget is RSM11_STOP_BUDGET).
INV_GATE ==
    /\ inputs.selector = "AUTO" \/ session_mode = "AUTO"
    /\ ~inputs.gate_a \/ ~inputs.gate_b
    /\ drive_enable
    => Cat1Ramp

\* INV-ENABLE (RSM-09): in a manual session, the enabling device fully
\* pressed on either channel removes power (Cat 0); not in the middle
\* position on both channels, drives stay enabled only during a Cat 1 ramp.
INV_ENABLE ==
    session_mode \in {"T1", "T2"} /\ drive_enable =>
        /\ inputs.enable_a # "PANIC" /\ inputs.enable_b # "PANIC"
        /\ (inputs.enable_a = "MIDDLE" /\ inputs.enable_b = "MIDDLE") \/ Cat1Ramp

\* RSM-11: every stop reaches standstill within MaxStopCycles of its FIRST
\* trigger: once the ramp-down output has been on for more than
\* MaxStopCycles + 1 consecutive cycles (the trigger cycle, then
\* MaxStopCycles full cycles), no cycle reads the arm moving.  The episode
\* is the ramp-down output's, so a standstill reading in the cycle of an
\* escalation from Cat 2 to Cat 1 does not restart it; a command accepted in
\* a cycle that reads standstill (a Servo-off when the Cat 2 stop has just
\* reached HOLD) is a new trigger and starts a new episode.
RSM11_STOP_BUDGET == obs_ramp > MaxStopCycles + 1 => inputs.speed = "ZERO"

\* RSM-11: a Pause is a Cat 2 stop: power kept, ramp-down requested.
RSM11_PAUSE_CAT2 ==
    last_accepted = "PAUSE" => contactor_closed /\ ramp_down_request /\ stop_category = "CAT2"

\* RSM-11/RSM-03 (standstill monitoring, IEC 60204-1 Cat 2): with power on
\* and no motion commanded, measured motion removes power (Cat 0) and shows
\* a fault (or the E-stop removed power in the same cycle).
RSM11_STANDSTILL == obs_unexpected_motion => Unpowered /\ Locked

\* INV-NOJOG-AUTO (RSM-08): no jog speed is commanded in AUTO (selector or
\* session), and a jog command in AUTO is rejected with its reason
\* (JOG_IN_AUTO; LOCKED_OUT in lockout) and accepted never.
INV_NOJOG_AUTO ==
    /\ commanded_speed_mm_s > 0 => inputs.selector # "AUTO" /\ session_mode # "AUTO"
    /\ jog_in_auto => command_result \in {"JOG_IN_AUTO", "LOCKED_OUT"}

\* RSM-09: a jog start is accepted only in a manual session with the
\* enabling device in its middle position on both channels.
RSM09_JOG_START ==
    last_accepted = "JOG_START" =>
        /\ session_mode \in {"T1", "T2"} /\ inputs.selector = session_mode
        /\ inputs.enable_a = "MIDDLE" /\ inputs.enable_b = "MIDDLE"

\* RSM-08: Start is accepted only in an AUTO session with the safeguard
\* closed on both channels.
RSM08_START ==
    last_accepted = "START" =>
        /\ session_mode = "AUTO" /\ inputs.selector = "AUTO"
        /\ inputs.gate_a /\ inputs.gate_b

\* INV-T1SPEED (RSM-10): in T1 the commanded speed at the tool centre point
\* never exceeds T1SpeedLimit, and a cycle that measures OVER_T1 in a T1
\* session ends with the power outputs off.  (The TCP speed with the tool
\* offset is computed in the C++ kinematics; the model sees its level.)
INV_T1SPEED ==
    /\ session_mode = "T1" => commanded_speed_mm_s <= T1MaxSpeed
    /\ t1_overspeed => Unpowered /\ Locked

\* RSM-06: Servo-on is accepted only unpowered, after any E-stop demand has
\* been reset, with no drive fault, a valid mode that becomes the session's,
\* and: AUTO - safeguard closed; T1/T2 - enabling device middle; T2 - a T2
\* confirmation accepted since the selector was last moved off T2.
RSM06_SERVO_ON ==
    last_accepted = "SERVO_ON" =>
        /\ ~obs_servo_on_powered /\ ~obs_guard_fault /\ obs_estop = "CLEAR"
        /\ inputs.selector \in Modes /\ session_mode = inputs.selector
        /\ inputs.selector = "AUTO" => inputs.gate_a /\ inputs.gate_b
        /\ inputs.selector \in {"T1", "T2"} =>
               inputs.enable_a = "MIDDLE" /\ inputs.enable_b = "MIDDLE"
        /\ inputs.selector = "T2" => obs_t2 \in 1..(T2ConfirmTimeoutCycles + 1)

\* RSM-07/RSM-03: a drive fault read while powered removes power (Cat 0)
\* and shows a fault (or the E-stop removed power in the same cycle).
RSM07_DRIVE_FAULT == obs_drive_fault => Unpowered /\ Locked

\* RSM-07 (arming timeout) and RSM-15 (timing in cycles, whatever the
\* commands processed), UCA-RSM-04: drive enable stays on without the drives
\* reporting ready for at most ArmingTimeoutCycles + 1 consecutive cycles.
RSM07_ARMING_TIMEOUT == obs_arming <= ArmingTimeoutCycles + 1

\* UCA-RSM-02 (RSM-07, issue 29 item 2): the brakes are released only with
\* the contactor closed and the drives enabled since the previous cycle at
\* least, and only in a cycle whose drives report ready (contactor -> servo
\* on -> brake release; a gravity-loaded axis never hangs on a drive that
\* is not ready).
UCA_BRAKE_ORDER ==
    brake_release => contactor_closed /\ drive_enable /\ obs_was_enabled /\ inputs.servo_ready

\* UCA-RSM-03 (RSM-07, RSM-03, issue 29 item 3): a cycle that reads the
\* drives not ready with the brakes released ends with every power output
\* off and a fault shown (bound: the same cycle).
UCA_READY_LOST == obs_ready_lost => Unpowered /\ Locked

\* UCA-RSM-12 (RSM-10, RSM-03, ISO 10218-1 5.7.4 / 5.4.3, issue 29 item 5): in a T2
\* session no jog speed above the T2 limit is commanded, and a cycle that
\* measures the TCP above the T2 limit ends with every power output off and a
\* fault shown (bound: the same cycle; Cat 0, design page §13).
UCA_T2_OVERSPEED ==
    /\ session_mode = "T2" => commanded_speed_mm_s <= T2SpeedLimit
    /\ obs_t2_overspeed => Unpowered /\ Locked

\* UCA-RSM-13 (RSM-03, RSM-07, issue 29 item 10): a contactor feedback (the
\* safety relay's auxiliary contact) or a brake feedback that disagrees with
\* its command for FeedbackCycles + 1 consecutive cycles with the command
\* unchanged ends that cycle with every power output off and a fault shown
\* (bound: FeedbackCycles + 1 cycles of disagreement; a welded contactor is
\* seen while it is commanded open, a brake that does not release while
\* commanded released).
UCA_FEEDBACK ==
    obs_fb_contactor > FeedbackCycles \/ obs_fb_brake > FeedbackCycles => Unpowered /\ Locked

\* UCA-RSM-15 (RSM-03, RSM-07, RSM-04; the converse of UCA-RSM-13 and of
\* INV-DISCREPANCY): no monitoring lockout without its cause.  A feedback
\* lockout is shown only after its feedback disagreed with the output it
\* monitors for FeedbackCycles + 1 consecutive cycles under one command (a
\* command change gives the device its full switching time again), a
\* discrepancy lockout only after its channels disagreed (or the selector
\* read invalid) for D + 1 consecutive cycles: a healthy device switching
\* within its time, or a discrepancy shorter than the discrepancy time, never
\* removes power (Cat 0) from a moving arm.
UCA_FEEDBACK_CAUSE ==
    /\ fault_code = "CONTACTOR_FEEDBACK" => obs_fb_contactor > FeedbackCycles
    /\ fault_code = "BRAKE_FEEDBACK" => obs_fb_brake > FeedbackCycles

UCA_DISCREPANCY_CAUSE ==
    /\ fault_code = "DISCREPANCY_ESTOP" => obs_disagree.estop > D
    /\ fault_code = "DISCREPANCY_SAFEGUARD" => obs_disagree.gate > D
    /\ fault_code = "DISCREPANCY_ENABLING" => obs_disagree.enable > D
    /\ fault_code = "SELECTOR_INVALID" => obs_disagree.selector > D

\* UCA-RSM-14 (RSM-09, RSM-17, issue 29 item 5 "nothing checks that only the
\* jogged axis moves"): while a jog speed is commanded, the jogged axis is the
\* one the accepted JOG_START named, one of the robot's six joints, and no
\* other axis is commanded into a PLCopen motion state (bound: every cycle of
\* the jog, the cycle that accepts it included).
UCA_JOG_AXIS ==
    commanded_speed_mm_s > 0 =>
        /\ obs_jog_axis \in RobotJoints
        /\ \A i \in DOMAIN axes : i # obs_jog_axis => axes[i] \notin PLCopen!MotionStates

\* UCA-RSM-16 (RSM-11, IEC 60204-1 9.2.2: a Cat 1 stop removes power only
\* once the stop is achieved): a ramped stop -- the ramp-down request on at
\* the start of a cycle -- ends with a power output removed only in a cycle
\* that read standstill, or with a Cat 0 cause read or shown in that cycle:
\* a fault shown, an E-stop demand, the enabling device in PANIC in a manual
\* session.  Power removed while the arm still moves turns the controlled
\* stop into an uncontrolled one, whose stopping distance is not the one the
\* risk assessment chose Cat 1 for (bound: the cycle that removes it).
UCA_STOP_POWER_AT_STANDSTILL ==
    obs_ramp_cut.session # "NONE" =>
        \/ obs_ramp_cut.speed = "ZERO"
        \/ Locked
        \/ EstopTripped(inputs)
        \/ EnablePanic(inputs) /\ obs_ramp_cut.session \in {"T1", "T2"}

\* UCA-RSM-05 (RSM-09, ISO 10218-1 5.8.3, issue 29 item 6): once the
\* enabling device was read in PANIC (either channel), no drive is enabled
\* in a manual session until both channels were read RELEASED.
UCA_PANIC_REARM ==
    drive_enable /\ session_mode \in {"T1", "T2"} => ~obs_panic

\* RSM-13: a cycle that began with a command queued answers it: ACCEPTED, or
\* its reason code, also shown as the last reject reason.
RSM13_RESULT ==
    obs_popped => \/ command_result = "ACCEPTED"
                  \/ command_result \in Reasons /\ last_reject_reason = command_result

\* RSM-14: a Submit is queued (queue_length + 1) when the queue is not full,
\* else rejected at once with QUEUE_FULL and nothing else queued: nothing is
\* dropped silently.
RSM14_QUEUE == ~obs_submit_lost

\* RSM-12: a failed self-test in the first cycle locks out for good.
RSM12_SELF_TEST == obs_self_test_failed => fault_code = "SELF_TEST_FAILED" /\ Unpowered

\* RSM-17: without power every axis is Disabled (ErrorStop after a drive
\* fault, which puts every axis in ErrorStop).
RSM17_AXES ==
    /\ Unpowered => \A i \in Axes : axes[i] \in {"Disabled", "ErrorStop"}
    /\ fault_code = "DRIVE_FAULT" => \A i \in Axes : axes[i] = "ErrorStop"

\* INV-1OO2 (RSM-04): a tripped channel of a safety input that guards the
\* current mode never coexists with commanded motion (a jog speed or an
\* axis in motion): E-stop always, safeguard in AUTO, enabling device in
\* T1/T2 (the safeguard is not required in manual modes, RSM-09).
INV_1OO2 ==
    (commanded_speed_mm_s > 0 \/ \E i \in Axes : axes[i] \in PLCopen!MotionStates) =>
        /\ inputs.estop_a /\ inputs.estop_b
        /\ session_mode = "AUTO" => inputs.gate_a /\ inputs.gate_b
        /\ session_mode \in {"T1", "T2"} =>
               inputs.enable_a = "MIDDLE" /\ inputs.enable_b = "MIDDLE"

\* RSM-13 / seed 3.1 (issue 16, "if the PC hangs, the robot must stay
\* safe"): the cycle that reads the operator link lost (heartbeat expired)
\* while a jog speed is commanded ends the jog: no jog speed, no axis in
\* motion, and a Cat 2 stop with power kept -- Cat 1 if that cycle also
\* accepted a queued Servo-off, a lockout if a discrepancy counter expired.
RSM13_LINK_LOSS ==
    obs_link_lost =>
        /\ commanded_speed_mm_s = 0
        /\ \A i \in Axes : axes[i] \notin PLCopen!MotionStates
        /\ \/ Locked
           \/ /\ contactor_closed /\ ramp_down_request
              /\ stop_category = "CAT2" \/ last_accepted = "SERVO_OFF"

(***************************************************************************)
(* Witnesses (vacuity): each is the negation of an invariant's antecedent; *)
(* the checker must find a state violating it, i.e. reach the antecedent.  *)
(***************************************************************************)
Witness_INV_RESET            == ~(contactor_closed \/ drive_enable \/ brake_release)
Witness_RSM05_RESET_ACCEPTED == ~(last_accepted = "RESET")
Witness_RSM04_CHANNEL_TEST   == ~(last_accepted = "RESET")
Witness_RSM03_ESTOP_CAT0     == ~((~inputs.estop_a \/ ~inputs.estop_b) /\ obs_booted)
Witness_INV_DISCREPANCY      == ~(obs_disagree.estop > D \/ obs_disagree.gate > D
                                  \/ obs_disagree.enable > D \/ obs_disagree.selector > D)
Witness_RSM03_FIELDBUS       == ~obs_fieldbus_lost
Witness_RSM02_MODE_CHANGE    == ~(drive_enable /\ inputs.selector # session_mode)
Witness_INV_GATE             == ~((inputs.selector = "AUTO" \/ session_mode = "AUTO")
                                  /\ (~inputs.gate_a \/ ~inputs.gate_b) /\ drive_enable)
Witness_INV_ENABLE           == ~(session_mode \in {"T1", "T2"} /\ drive_enable
                                  /\ (inputs.enable_a # "MIDDLE" \/ inputs.enable_b # "MIDDLE"))
Witness_RSM11_STOP_BUDGET    == ~(obs_ramp > MaxStopCycles + 1)
Witness_RSM11_PAUSE_CAT2     == ~(last_accepted = "PAUSE")
Witness_RSM11_STANDSTILL     == ~obs_unexpected_motion
Witness_INV_NOJOG_AUTO       == ~(jog_in_auto /\ command_result = "JOG_IN_AUTO")
Witness_RSM09_JOG_START      == ~(last_accepted = "JOG_START")
Witness_RSM08_START          == ~(last_accepted = "START")
Witness_INV_T1SPEED          == ~t1_overspeed
Witness_RSM06_SERVO_ON       == ~(last_accepted = "SERVO_ON" /\ inputs.selector = "T2")
Witness_RSM07_DRIVE_FAULT    == ~obs_drive_fault
\* (issue 29 item 7: an E-stop demand in the cycle that reads the drive fault)
Witness_RSM07_DRIVE_FAULT_ESTOP == ~(obs_drive_fault /\ (~inputs.estop_a \/ ~inputs.estop_b))
Witness_RSM12_SELF_TEST      == ~obs_self_test_failed
Witness_RSM07_ARMING_TIMEOUT == ~(obs_arming = ArmingTimeoutCycles + 1)
Witness_UCA_BRAKE_ORDER      == ~brake_release
Witness_UCA_READY_LOST       == ~obs_ready_lost
Witness_UCA_T2_OVERSPEED     == ~obs_t2_overspeed
Witness_UCA_FEEDBACK         == ~(obs_fb_contactor > FeedbackCycles)
Witness_UCA_FEEDBACK_BRAKE   == ~(obs_fb_brake > FeedbackCycles)
\* (a welded contactor: the lockout with the contactor commanded open; one
\* that does not pull in: commanded closed; the brake's: each needs the
\* disagreement offered outside lockout)
Witness_UCA_FEEDBACK_CAUSE   == ~(fault_code = "CONTACTOR_FEEDBACK" /\ ~obs_was_enabled)
Witness_UCA_FEEDBACK_CAUSE_ON == ~(fault_code = "CONTACTOR_FEEDBACK" /\ obs_was_enabled)
Witness_UCA_FEEDBACK_CAUSE_BRAKE == ~(fault_code = "BRAKE_FEEDBACK")
Witness_UCA_DISCREPANCY_CAUSE == ~(fault_code = "DISCREPANCY_ESTOP")
\* (a jog on its axis, and one resumed after a Pause)
Witness_UCA_JOG_AXIS         == ~(commanded_speed_mm_s > 0)
Witness_UCA_JOG_AXIS_RESUMED == ~(commanded_speed_mm_s > 0 /\ last_accepted = "RESUME")
\* (the panic observer set and the device back in MIDDLE, unpowered)
Witness_UCA_STOP_POWER_AT_STANDSTILL == ~(obs_ramp_cut.session # "NONE" /\ ~Locked)
Witness_UCA_PANIC_REARM      == ~(obs_panic /\ inputs.enable_a = "MIDDLE" /\ inputs.enable_b = "MIDDLE")
Witness_RSM13_RESULT         == ~(obs_popped /\ command_result # "ACCEPTED")
\* (a full queue: the next Submit takes RSM-14's QUEUE_FULL branch; that Submit
\* itself changes only last_reject_reason, outside the View, so it adds no state)
Witness_RSM14_QUEUE          == ~(queue_length = QueueCapacity)
Witness_RSM17_AXES           == ~(fault_code = "DRIVE_FAULT")
Witness_RSM13_LINK_LOSS      == ~obs_link_lost
Witness_INV_1OO2             == ~(\E i \in Axes : axes[i] \in PLCopen!MotionStates)
\* (the lockout part: the E-stop part is INV_RESET's witness)
Witness_INV_POWER            == ~Locked

-----------------------------------------------------------------------------
(*********** Input profiles, substituted by the .cfg files with <- *********)
(* (TLC's .cfg syntax has no tuples or records.)                          *)
Jog(ax, dir, v) == [kind |-> "JOG_START", axis |-> ax, direction |-> dir, speed_mm_s |-> v]

\* CI: a valid jog above T1SpeedLimit (clamped in T1 only) and an invalid
\* one (axis 7).  Full: also a valid slow jog and two more invalid ones.
CI_JogCommands   == {Jog(2, -1, 400), Jog(7, 1, 100)}
Full_JogCommands == {Jog(1, 1, 100), Jog(2, -1, 400), Jog(7, 1, 100),
                     Jog(3, 0, 100), Jog(4, 1, 0)}

\* Pairs: healthy, and channel B alone tripped (a trip and a disagreement).
CI_ChannelPairs  == {<<TRUE, TRUE>>, <<TRUE, FALSE>>}
\* E-stop: also both channels open (a normal press), so that the test of
\* both channels (K37) can pass and a Reset be accepted.
CI_EstopPairs    == {<<TRUE, TRUE>>, <<TRUE, FALSE>>, <<FALSE, FALSE>>}
All_ChannelPairs == {<<a, b>> : a \in BOOLEAN, b \in BOOLEAN}
\* Full cfg (long timers): only consistent readings where a disagreement
\* would let a 50-cycle counter run along a 1000-cycle timer.
Consistent_ChannelPairs == {<<TRUE, TRUE>>, <<FALSE, FALSE>>}
Full_JogCommands_Small  == {Jog(2, -1, 400)}
Consistent_EnablingPairs == {<<"RELEASED", "RELEASED">>, <<"MIDDLE", "MIDDLE">>}
\* Enabling: released, middle, and one channel fully pressed (panic, not
\* middle, and a disagreement).
CI_EnablingPairs  == {<<"RELEASED", "RELEASED">>, <<"MIDDLE", "MIDDLE">>,
                      <<"MIDDLE", "PANIC">>}
All_EnablingPairs == {<<a, b>> : a \in EnablePositions, b \in EnablePositions}

-----------------------------------------------------------------------------
(***************** Row reachability (for the coverage check) ***************)
\* The §5 and §6 rows that the next cycle fires from the current state,
\* for every input vector the environment may present next.
RowsFiredBy(in) ==
    LET m2 == AfterSafety(in)
        k  == IF queue = << >> THEN {}
              ELSE {CommandRow([m2 EXCEPT !.queue = Tail(@)], Head(queue), in)}
    IN {SafetyRow(Monitored(in), in)} \cup k

NextRows == UNION {RowsFiredBy(in) : in \in NextInputs(inputs)}

\* "Row r never fires": TLC must find a violation for every reachable row.
RowNeverFires(r) == r \notin NextRows

=============================================================================
