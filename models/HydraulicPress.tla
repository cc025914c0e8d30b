---------------------------- MODULE HydraulicPress ----------------------------
(* The hydraulic press of docs/design/hydraulic-press.md (SCH-05) on the     *)
(* state-chain engine (EXTENDS StateChain; the tree is given to its         *)
(* constants in HydraulicPress.cfg). One step = one scan with one input      *)
(* event; the run function of the one state that reacts makes one request.  *)
EXTENDS StateChain

StepNames == <<"Ready", "Feed", "Locate", "Clamp", "FastAdvance", "Pressing", "Blow", "Eject", "ClearScrap">>
PressOrder == <<"Press", "MotorOff", "MotorOn", "Stroke", "Mode1", "M1_Ready", "M1_Feed", "M1_Locate", "M1_Clamp", "M1_FastAdvance", "M1_Pressing", "M1_Blow", "M1_Eject", "M1_ClearScrap", "Mode2", "M2_Ready", "M2_Feed", "M2_Locate", "M2_Clamp", "M2_FastAdvance", "M2_Pressing", "M2_Blow", "M2_Eject", "M2_ClearScrap", "Mode3", "M3_Ready", "M3_Feed", "M3_Locate", "M3_Clamp", "M3_FastAdvance", "M3_Pressing", "M3_Blow", "M3_Eject", "M3_ClearScrap", "Aux", "CoolIdle", "Cooling">>
PressStates == {PressOrder[i] : i \in 1..Len(PressOrder)}
ModeStates == {"Mode1", "Mode2", "Mode3"}
ModeOf == <<"Mode1", "Mode2", "Mode3">>
\* The stroke state of mode m at step k (1 = Ready .. 9 = ClearScrap).
StrokeState(m, k) == PressOrder[4 + (m - 1) * 10 + 1 + k]
StrokeStates == {StrokeState(m, k) : m \in 1..3, k \in 1..9}
StepIndex(s) == CHOOSE k \in 1..9 : \E m \in 1..3 : StrokeState(m, k) = s
PressParent ==
    [s \in PressStates |->
        CASE s = "Press" -> "none"
          [] s \in {"MotorOff", "MotorOn"} -> "Press"
          [] s \in {"Stroke", "Aux"} -> "MotorOn"
          [] s \in ModeStates -> "Stroke"
          [] s \in {"CoolIdle", "Cooling"} -> "Aux"
          [] OTHER -> ModeOf[CHOOSE m \in 1..3 : \E k \in 1..9 : StrokeState(m, k) = s]]
PressInitial ==
    [s \in PressStates |->
        CASE s = "Press" -> "MotorOff"
          [] s = "Stroke" -> "Mode1"
          [] s = "Aux" -> "CoolIdle"
          [] s \in ModeStates -> StrokeState(CHOOSE i \in 1..3 : ModeOf[i] = s, 1)
          [] OTHER -> "none"]
PressParallel == {"MotorOn"}

\* Outputs per state: set by the entry function, cleared by the exit function.
Valves == <<"none", "feed_valve", "locate_valve", "clamp_valve", "fast_valve", "press_valve", "blow_valve", "eject_valve", "scrap_valve">>
StrokeOutputs == {Valves[k] : k \in 2..9}
Out(s) ==
    CASE s = "MotorOn" -> "motor"
      [] s = "Aux" -> "lamp"
      [] s = "Cooling" -> "cool_pump"
      [] s \in StrokeStates -> Valves[StepIndex(s)]
      [] OTHER -> "none"

Inputs == {"motor_on", "motor_off", "start", "ret", "step_done", "mode1", "mode2", "mode3",
           "continuous_on", "continuous_off", "temp_high", "temp_ok"}

VARIABLES outputs, continuous, restarted, event
vars == <<chainVars, outputs, continuous, restarted, event>>

\* Observables shared with HydraulicPressFlat (docs/design/hydraulic-press.md §6).
motor == "motor" \in outputs
ActiveStep == {s \in StrokeStates : s \in active}
step == IF ActiveStep = {} THEN "none" ELSE StepNames[StepIndex(CHOOSE s \in ActiveStep : TRUE)]
mode == IF ModeStates \cap active = {} THEN 0 ELSE CHOOSE m \in 1..3 : ModeOf[m] \in active

\* §4: the request the run functions make for input e (none: <<>>).
InputMode(e) == CASE e = "mode1" -> 1 [] e = "mode2" -> 2 [] e = "mode3" -> 3 [] OTHER -> 0
NextStep(k) == IF k < 9 THEN k + 1 ELSE IF continuous THEN 2 ELSE 1
Reaction(e) ==
    CASE e = "motor_on" /\ "MotorOff" \in active -> <<"MotorOff", "MotorOn">>
      [] e = "motor_off" /\ "MotorOn" \in active -> <<"MotorOn", "MotorOff">>
      [] InputMode(e) # 0 /\ mode \notin {0, InputMode(e)} -> <<ModeOf[mode], ModeOf[InputMode(e)]>>
      [] e = "ret" /\ mode # 0 -> <<ModeOf[mode], ModeOf[mode]>>
      [] e = "start" /\ step = "Ready" -> <<StrokeState(mode, 1), StrokeState(mode, 2)>>
      [] e = "step_done" /\ step \notin {"none", "Ready"} ->
            LET k == CHOOSE i \in 1..9 : StepNames[i] = step
            IN <<StrokeState(mode, k), StrokeState(mode, NextStep(k))>>
      [] e = "temp_high" /\ "CoolIdle" \in active -> <<"CoolIdle", "Cooling">>
      [] e = "temp_ok" /\ "Cooling" \in active -> <<"Cooling", "CoolIdle">>
      [] OTHER -> <<>>

ApplyLog(outs, lg) ==
    (outs \ {Out(lg[i].state) : i \in {j \in DOMAIN lg : lg[j].kind = "exit"}})
        \cup ({Out(lg[i].state) : i \in {j \in DOMAIN lg : lg[j].kind = "entry"}} \ {"none"})

Init ==
    /\ ChainInit
    /\ outputs = ApplyLog({}, log)
    /\ continuous = FALSE
    /\ restarted = FALSE
    /\ event = "init"

Scan(e) ==
    LET r == Reaction(e) IN
    /\ IF r = <<>> THEN /\ log' = <<>> /\ result' = "ok" /\ UNCHANGED <<active, request>>
                     ELSE Request(r[1], r[2])
    /\ outputs' = ApplyLog(outputs, log')
    /\ continuous' = CASE e = "continuous_on" -> TRUE [] e = "continuous_off" -> FALSE [] OTHER -> continuous
    /\ restarted' = (e = "motor_on" /\ ~motor)
    /\ event' = e

Next == \E e \in Inputs : Scan(e)

PressSpec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
\* SCH-05 INV-PRESS: with the motor off no stroke output is on; a motor
\* restart starts at Ready with every stroke output off (never mid-stroke).
INV_PRESS ==
    /\ ~motor => outputs \cap StrokeOutputs = {}
    /\ restarted => step = "Ready" /\ outputs \cap StrokeOutputs = {}
\* SCH-05: the energised outputs are exactly those of the active states.
INV_PRESS_OUTPUTS_OF_ACTIVE == outputs = {Out(s) : s \in active} \ {"none"}

Witness_RestartAfterStroke == ~(restarted /\ mode = 1)  \* INV_PRESS (restart conjunct)
Witness_MidStroke == step \notin {"Pressing"}          \* INV_PRESS_OUTPUTS_OF_ACTIVE
Witness_Cooling == ~("cool_pump" \in outputs /\ step = "Eject")
===============================================================================
