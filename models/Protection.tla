------------------------------ MODULE Protection ------------------------------
(***************************************************************************)
(* PRO-01 .. PRO-04: ao_safety with its latched protection state machine   *)
(* sm_protection (docs/design/protection.md, "the page").  One step of     *)
(* this model is one tick: the validated sensor snapshot of the tick (page *)
(* section 2) is evaluated by rows P01..P05 (section 4); the output gate   *)
(* sets the fan command and diagnostics receives the operating status in   *)
(* the same tick (dispatch order monitoring, control, safety, diagnostics).*)
(*                                                                         *)
(* Environment: any snapshot in any tick (temperatures 0..TempLimit+1,     *)
(* voltages VoltMin-1..VoltMax+1: every boundary and both of its sides),   *)
(* valid or not, with or without a clear request, with or without the      *)
(* event's hazard_detected flag (the fan driver's fault line, page 2), and *)
(* the supervisor's lifecycle event delivered before it (EVT_DEGRADED,     *)
(* EVT_RECOVERY or none; page 4a).                                         *)
(*                                                                         *)
(* Outputs: the fan command and the equipment permissive; PROTECTION       *)
(* drives both to outputs_disabled (permissive off, fan at the safe value),*)
(* a state normal regulation never produces (page 4).                      *)
(***************************************************************************)
EXTENDS Naturals

CONSTANTS
    TempLimit,            \* 85 degC: hazard if temp > TempLimit (strict)
    VoltMin,              \* 18 V (180 dV): hazard if volt < VoltMin (strict)
    VoltMax,              \* 30 V (300 dV): hazard if volt > VoltMax (strict)
    ResponseBudgetTicks   \* PRO-04: 1 s = 10 ticks of 100 ms

ASSUME TempLimit \in Nat
ASSUME VoltMin \in Nat \ {0}
ASSUME VoltMax \in Nat /\ VoltMin <= VoltMax
ASSUME ResponseBudgetTicks \in Nat \ {0}

Temps == 0..(TempLimit + 1)
Volts == (VoltMin - 1)..(VoltMax + 1)
ProtectionStates == {"NORMAL", "PROTECTION"}
Results == {"OK", "PROTECTION_ENTERED", "LATCH_BLOCKED"}
FanCommands == {"REGULATED", "SAFE"}
FaultEvents == {"NONE", "SENSOR_INVALID", "OVER_TEMP", "UNDER_VOLT", "OVER_VOLT",
                "LATCH_BLOCKED", "HAZARD_DETECTED"}
Lifecycle == {"NONE", "DEGRADED", "RECOVERY"}

\* Inputs of the tick (the snapshot, the event's hazard_detected, the
\* lifecycle event delivered before it) ...
VARIABLES temp, volt, valid, clear, hazard_in, lifecycle
\* ... outputs of the tick (load_enable: the equipment permissive) ...
VARIABLES protection_state, latch_active, override_active, fan_cmd, load_enable,
          result, published, fault_event
\* ... ao_safety's degraded mode (EVT_DEGRADED until EVT_RECOVERY) ...
VARIABLES degraded
\* ... and history: the state before the tick, consecutive hazardous ticks.
VARIABLES was_protection, hazard_ticks

vars == <<temp, volt, valid, clear, hazard_in, lifecycle, protection_state,
          latch_active, override_active, fan_cmd, load_enable, result, published,
          fault_event, degraded, was_protection, hazard_ticks>>

-----------------------------------------------------------------------------
(***************************** Hazard (page 3) *****************************)
Hazard(t, v, ok, hz) == t > TempLimit \/ v < VoltMin \/ v > VoltMax \/ ~ok \/ hz

Cause(t, v, ok, hz) ==
    IF ~ok THEN "SENSOR_INVALID"
    ELSE IF t > TempLimit THEN "OVER_TEMP"
    ELSE IF v < VoltMin THEN "UNDER_VOLT"
    ELSE IF v > VoltMax THEN "OVER_VOLT"
    ELSE IF hz THEN "HAZARD_DETECTED"
    ELSE "NONE"

\* ao_safety's degraded mode after the lifecycle event lc (page 4a).
DegradedAfter(lc) ==
    IF lc = "DEGRADED" THEN TRUE ELSE IF lc = "RECOVERY" THEN FALSE ELSE degraded

(************************* Rows P01..P05 (page 4) ***************************)
\* The latch guard of a clear (P03/P04): a hazard, or the controller degraded.
Row(t, v, ok, clr, hz, dg) ==
    IF protection_state = "NORMAL" THEN
        IF Hazard(t, v, ok, hz) THEN "P01" ELSE "P02"
    ELSE IF clr /\ (Hazard(t, v, ok, hz) \/ dg) THEN "P03"
    ELSE IF clr THEN "P04"
    ELSE "P05"

NextState(row) ==
    IF row = "P01" THEN "PROTECTION"
    ELSE IF row = "P04" THEN "NORMAL"
    ELSE protection_state

\* The row a snapshot fires, for the conformance harness (the C++ reports it):
\* p is the record [t, v, ok, clr, hz, lc] of Tick's parameters.
RowsFiredBy(p) == {Row(p.t, p.v, p.ok, p.clr, p.hz, DegradedAfter(p.lc))}

Tick(t, v, ok, clr, hz, lc) ==
    LET dg == DegradedAfter(lc)
        row == Row(t, v, ok, clr, hz, dg)
        s == NextState(row) IN
    /\ temp' = t /\ volt' = v /\ valid' = ok /\ clear' = clr
    /\ hazard_in' = hz /\ lifecycle' = lc
    /\ degraded' = dg
    /\ protection_state' = s
    /\ latch_active' = (s = "PROTECTION")
    /\ override_active' = (s = "PROTECTION")
    \* Output gate: the safe fan value while the override is active.
    /\ fan_cmd' = IF s = "PROTECTION" THEN "SAFE" ELSE "REGULATED"
    /\ load_enable' = (s = "NORMAL")
    /\ result' = IF row = "P01" THEN "PROTECTION_ENTERED"
                 ELSE IF row = "P03" THEN "LATCH_BLOCKED"
                 ELSE "OK"
    \* Diagnostics runs after safety in the same tick.
    /\ published' = s
    /\ fault_event' = IF row = "P01" THEN Cause(t, v, ok, hz)
                      ELSE IF row = "P03" THEN "LATCH_BLOCKED"
                      ELSE "NONE"
    /\ was_protection' = (protection_state = "PROTECTION")
    /\ hazard_ticks' = IF Hazard(t, v, ok, hz)
                       THEN IF hazard_ticks < ResponseBudgetTicks
                            THEN hazard_ticks + 1 ELSE hazard_ticks
                       ELSE 0

\* Construction: NORMAL, no snapshot evaluated yet (a nominal reading).
Init ==
    /\ temp = 0 /\ volt = VoltMin /\ valid = TRUE /\ clear = FALSE
    /\ hazard_in = FALSE /\ lifecycle = "NONE" /\ degraded = FALSE
    /\ protection_state = "NORMAL" /\ latch_active = FALSE
    /\ override_active = FALSE /\ fan_cmd = "REGULATED" /\ load_enable = TRUE
    /\ result = "OK"
    /\ published = "NORMAL" /\ fault_event = "NONE"
    /\ was_protection = FALSE /\ hazard_ticks = 0

Next == \E t \in Temps, v \in Volts, ok \in BOOLEAN, clr \in BOOLEAN,
            hz \in BOOLEAN, lc \in Lifecycle :
            Tick(t, v, ok, clr, hz, lc)

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(******************************** Invariants *******************************)
\* PRO-02: every variable in its type: the context's protection state, latch and
\* output override, and the results OK / PROTECTION_ENTERED / LATCH_BLOCKED (the
\* tick of the last transition is not modelled: no invariant reads it).
TypeOK ==
    /\ temp \in Temps /\ volt \in Volts /\ valid \in BOOLEAN /\ clear \in BOOLEAN
    /\ hazard_in \in BOOLEAN /\ lifecycle \in Lifecycle /\ degraded \in BOOLEAN
    /\ protection_state \in ProtectionStates
    /\ latch_active \in BOOLEAN /\ override_active \in BOOLEAN
    /\ fan_cmd \in FanCommands /\ load_enable \in BOOLEAN /\ result \in Results
    /\ published \in ProtectionStates /\ fault_event \in FaultEvents
    /\ was_protection \in BOOLEAN
    /\ hazard_ticks \in 0..ResponseBudgetTicks

\* The invariants spell the hazard out from the requirement (not Hazard
\* above), so that a mutant of the rows' operators cannot weaken them.
InputHazard ==
    temp > TempLimit \/ volt < VoltMin \/ volt > VoltMax \/ ~valid \/ hazard_in

\* The controller is degraded for this tick: EVT_DEGRADED delivered now, or
\* earlier and no EVT_RECOVERY since (degraded is the previous tick's mode
\* only when no lifecycle event came).
DegradedNow ==
    lifecycle = "DEGRADED" \/ (lifecycle = "NONE" /\ degraded)

\* The outputs in the protective state: outputs_disabled of the seed's
\* timing diagram (permissive off, fan at its safe value).
OutputsDisabled == ~load_enable /\ fan_cmd = "SAFE"

\* PRO-01, PRO-03 (UCA-P1): a hazardous snapshot - a limit crossed, an
\* invalid sensor or the event's hazard_detected - leaves ao_safety in
\* PROTECTION with the outputs disabled in the same tick.
INV_PRO_HAZARD_PROTECTS ==
    InputHazard => protection_state = "PROTECTION" /\ OutputsDisabled

\* PRO-02 (UCA-P2, UCA-P3, UCA-P6): the latch.  The outputs come back (NORMAL)
\* only on a clear request in a snapshot without a hazard while the
\* controller is not degraded - EVT_RECOVERY alone never releases them; a
\* clear request with a hazard or in Degraded is denied; a clear request on
\* a healthy controller without a hazard is never refused.
INV_PRO_LATCH ==
    /\ (was_protection /\ protection_state = "NORMAL") => (clear /\ ~InputHazard /\ ~DegradedNow)
    /\ (was_protection /\ clear /\ (InputHazard \/ DegradedNow)) => result = "LATCH_BLOCKED"
    /\ (was_protection /\ clear /\ ~InputHazard /\ ~DegradedNow) => protection_state = "NORMAL"
    /\ degraded = DegradedNow

\* PRO-02, PRO-03 (UCA-P4): PROTECTION_ENTERED exactly on entry, with the
\* cause published to diagnostics: the first true condition in the order
\* of page 3; LATCH_BLOCKED only in PROTECTION on a clear request, and
\* published as such.
INV_PRO_RESULT ==
    /\ result = "PROTECTION_ENTERED"
           <=> (~was_protection /\ protection_state = "PROTECTION")
    /\ result = "LATCH_BLOCKED" => (was_protection /\ clear)
    /\ result = "LATCH_BLOCKED" <=> fault_event = "LATCH_BLOCKED"
    /\ result = "PROTECTION_ENTERED" =>
           fault_event = CASE ~valid -> "SENSOR_INVALID"
                           [] valid /\ temp > TempLimit -> "OVER_TEMP"
                           [] valid /\ temp <= TempLimit /\ volt < VoltMin -> "UNDER_VOLT"
                           [] valid /\ temp <= TempLimit /\ volt >= VoltMin /\ volt > VoltMax -> "OVER_VOLT"
                           [] OTHER -> "HAZARD_DETECTED"
    /\ result = "OK" => fault_event = "NONE"

\* PRO-03 (UCA-P5): in PROTECTION the latch and the override are on, the
\* outputs are disabled and diagnostics holds PROTECTION; outside it none
\* is: regulation keeps the permissive on and never writes the safe state.
INV_PRO_OVERRIDE ==
    /\ latch_active <=> protection_state = "PROTECTION"
    /\ override_active <=> protection_state = "PROTECTION"
    /\ fan_cmd = "SAFE" <=> protection_state = "PROTECTION"
    /\ load_enable <=> protection_state = "NORMAL"
    /\ published = protection_state
    /\ (result = "PROTECTION_ENTERED") => fault_event # "NONE"

\* PRO-04 (UCA-P7): a hazard present for the budget's number of ticks
\* implies protection, the outputs disabled and the status published.
INV_PRO_RESPONSE ==
    hazard_ticks >= ResponseBudgetTicks =>
        /\ protection_state = "PROTECTION"
        /\ OutputsDisabled
        /\ published = "PROTECTION"

-----------------------------------------------------------------------------
(* Reachability witnesses (non-vacuity): each Witness_X is the negation of *)
(* a situation an invariant speaks about; tests/python/test_pro_model.py   *)
(* checks each alone and expects it violated, i.e. the situation reachable.*)
Witness_OverTemp ==        \* INV_PRO_HAZARD_PROTECTS, temperature only
    ~(temp = TempLimit + 1 /\ valid /\ volt = VoltMin /\ result = "PROTECTION_ENTERED")
Witness_BoundaryNormal ==  \* INV_PRO_HAZARD_PROTECTS, every limit value is no hazard
    ~(temp = TempLimit /\ volt = VoltMax /\ valid /\ protection_state = "NORMAL")
Witness_Blocked ==         \* INV_PRO_LATCH, clear denied while hot
    ~(result = "LATCH_BLOCKED" /\ temp = TempLimit + 1)
Witness_Cleared ==         \* INV_PRO_LATCH, clear accepted when cool
    ~(was_protection /\ protection_state = "NORMAL")
Witness_LatchedCool ==     \* INV_PRO_LATCH, latched without a hazard
    ~(protection_state = "PROTECTION" /\ ~InputHazard /\ ~clear)
Witness_Entered ==         \* INV_PRO_RESULT, entry by an invalid sensor
    ~(result = "PROTECTION_ENTERED" /\ fault_event = "SENSOR_INVALID")
Witness_SafeFan ==         \* INV_PRO_OVERRIDE, under-voltage
    ~(fan_cmd = "SAFE" /\ fault_event = "UNDER_VOLT")
Witness_Budget ==          \* INV_PRO_RESPONSE, hazard for the whole budget
    ~(hazard_ticks = ResponseBudgetTicks /\ volt = VoltMax + 1)
Witness_Detected ==        \* INV_PRO_HAZARD_PROTECTS, hazard_detected alone disables the outputs
    ~(fault_event = "HAZARD_DETECTED" /\ temp = 0 /\ volt = VoltMin /\ valid /\ ~load_enable)
Witness_DegradedBlocked == \* INV_PRO_LATCH, clear denied in Degraded without a hazard
    ~(result = "LATCH_BLOCKED" /\ ~InputHazard /\ degraded)
Witness_RecoveredLatched == \* INV_PRO_LATCH, EVT_RECOVERY leaves the latch set
    ~(lifecycle = "RECOVERY" /\ was_protection /\ protection_state = "PROTECTION" /\ ~InputHazard)
=============================================================================
