---------------------------- MODULE HydraulicPress ----------------------------
(* The hydraulic press of docs/design/hydraulic-press.md (SCH-05) on the     *)
(* state-chain engine (EXTENDS StateChain; the tree is given to its         *)
(* constants in HydraulicPress.cfg). One step = one scan with one input      *)
(* event; the run function of the one state that reacts makes one request.  *)
(* The modes sit directly under the root (the document's Figure 1): each     *)
(* has its own stroke order and parameters, the selected mode survives a     *)
(* motor stop, and a mode change exits the whole motor-on subtree.           *)
EXTENDS StateChain

\* Per mode m (design page §3): the mode state, its motor-off / motor-on states, the
\* stroke sub-chain root, the aux sub-chain and the stroke states in stroke order.
ModeOf == <<"Mode1", "Mode2", "Mode3">>
OffOf == <<"M1_Off", "M2_Off", "M3_Off">>
OnOf == <<"M1_On", "M2_On", "M3_On">>
StrokeOf == <<"M1_Stroke", "M2_Stroke", "M3_Stroke">>
AuxOf == <<"M1_Aux", "M2_Aux", "M3_Aux">>
CoolIdleOf == <<"M1_CoolIdle", "M2_CoolIdle", "M3_CoolIdle">>
CoolingOf == <<"M1_Cooling", "M2_Cooling", "M3_Cooling">>
\* The stroke order of each mode, Ready first (design page §3, "Modes").
StepSeq ==
    << <<"Ready", "Feed", "Locate", "Clamp", "FastAdvance", "Pressing", "Blow", "Eject", "ClearScrap">>,
       <<"Ready", "Feed", "Locate", "Clamp", "FastAdvance", "Pressing", "Eject", "Blow", "ClearScrap">>,
       <<"Ready", "Feed", "Locate", "Clamp", "Pressing", "Eject", "ClearScrap">> >>
StrokeSeq ==
    << <<"M1_Ready", "M1_Feed", "M1_Locate", "M1_Clamp", "M1_FastAdvance", "M1_Pressing", "M1_Blow", "M1_Eject", "M1_ClearScrap">>,
       <<"M2_Ready", "M2_Feed", "M2_Locate", "M2_Clamp", "M2_FastAdvance", "M2_Pressing", "M2_Eject", "M2_Blow", "M2_ClearScrap">>,
       <<"M3_Ready", "M3_Feed", "M3_Locate", "M3_Clamp", "M3_Pressing", "M3_Eject", "M3_ClearScrap">> >>
\* The mode parameters (design page §3): press pressure in bar, fast-advance speed in mm/s.
Pressure == <<160, 120, 60>>
Speed == <<120, 80, 0>>

ModeBlock(m) == <<ModeOf[m], OffOf[m], OnOf[m], StrokeOf[m]>> \o StrokeSeq[m] \o <<AuxOf[m], CoolIdleOf[m], CoolingOf[m]>>
PressOrder == <<"Press">> \o ModeBlock(1) \o ModeBlock(2) \o ModeBlock(3)
PressStates == {PressOrder[i] : i \in 1..Len(PressOrder)}
ModeStates == {ModeOf[m] : m \in 1..3}
StrokeStates == {StrokeSeq[m][k] : m \in 1..3, k \in 1..7} \cup {StrokeSeq[m][k] : m \in 1..2, k \in 8..9}
StepState(m, k) == StrokeSeq[m][k]
\* Bounded ranges (1..16, 1..9) with a length guard rather than 1..Len(...): the prover
\* enumerates a CHOOSE or \E only over a range of constant bounds.
ModeNum(s) == CHOOSE m \in 1..3 : \E i \in 1..16 : i <= Len(ModeBlock(m)) /\ ModeBlock(m)[i] = s
StepNames == {"Ready", "Feed", "Locate", "Clamp", "FastAdvance", "Pressing", "Blow", "Eject", "ClearScrap"}
StepNameOf ==
    [s \in StrokeStates |->
        CHOOSE n \in StepNames : \E m \in 1..3 : \E k \in 1..9 :
            k <= Len(StrokeSeq[m]) /\ StrokeSeq[m][k] = s /\ StepSeq[m][k] = n]
PressParent ==
    [s \in PressStates |->
        CASE s = "Press" -> "none"
          [] s \in ModeStates -> "Press"
          [] s \in {OffOf[m] : m \in 1..3} \cup {OnOf[m] : m \in 1..3} -> ModeOf[ModeNum(s)]
          [] s \in {StrokeOf[m] : m \in 1..3} \cup {AuxOf[m] : m \in 1..3} -> OnOf[ModeNum(s)]
          [] s \in {CoolIdleOf[m] : m \in 1..3} \cup {CoolingOf[m] : m \in 1..3} -> AuxOf[ModeNum(s)]
          [] OTHER -> StrokeOf[ModeNum(s)]]
PressInitial ==
    [s \in PressStates |->
        CASE s = "Press" -> "Mode1"
          [] s \in ModeStates -> OffOf[ModeNum(s)]
          [] s \in {StrokeOf[m] : m \in 1..3} -> StepState(ModeNum(s), 1)
          [] s \in {AuxOf[m] : m \in 1..3} -> CoolIdleOf[ModeNum(s)]
          [] OTHER -> "none"]
PressParallel == {OnOf[m] : m \in 1..3}

\* Outputs per state: set by the entry function, cleared by the exit function.
ValveOf(n) ==
    CASE n = "Feed" -> "feed_valve" [] n = "Locate" -> "locate_valve" [] n = "Clamp" -> "clamp_valve"
      [] n = "FastAdvance" -> "fast_valve" [] n = "Pressing" -> "press_valve" [] n = "Blow" -> "blow_valve"
      [] n = "Eject" -> "eject_valve" [] n = "ClearScrap" -> "scrap_valve" [] OTHER -> "none"
StrokeOutputs == {"feed_valve", "locate_valve", "clamp_valve", "fast_valve", "press_valve", "blow_valve",
                  "eject_valve", "scrap_valve"}
Out(s) ==
    CASE s \in {OnOf[m] : m \in 1..3} -> "motor"
      [] s \in {AuxOf[m] : m \in 1..3} -> "lamp"
      [] s \in {CoolingOf[m] : m \in 1..3} -> "cool_pump"
      [] s \in StrokeStates -> ValveOf(StepNameOf[s])
      [] OTHER -> "none"

\* The stroke outputs of each mode's work cycle in their order (design page §3), spelt out
\* again for UCA-8 rather than read from StrokeSeq / StepSeq / ValveOf: the property must
\* not share the tables the reaction uses.
ValveOrder ==
    << <<"feed_valve", "locate_valve", "clamp_valve", "fast_valve", "press_valve", "blow_valve", "eject_valve", "scrap_valve">>,
       <<"feed_valve", "locate_valve", "clamp_valve", "fast_valve", "press_valve", "eject_valve", "blow_valve", "scrap_valve">>,
       <<"feed_valve", "locate_valve", "clamp_valve", "press_valve", "eject_valve", "scrap_valve">> >>
Skipped == 9

Inputs == {"motor_on", "motor_off", "start", "ret", "step_done", "mode1", "mode2", "mode3",
           "continuous_on", "continuous_off", "temp_high", "temp_ok"}

\* History variables of the hazard properties (design page §7), functions of the inputs
\* and outputs only: `selector` the mode last selected (the selector switch; 1 at
\* power-up), `cycleMode` the mode in which Start began the running work cycle (0: no
\* cycle: set by Start, kept while a stroke output stays on, cleared when none is on),
\* `clamped` the clamp valve has been on in this work cycle (cleared by the feed valve,
\* which begins a cycle, and when no stroke output is on), `motorCmd` a motor-start was
\* given and the motor has run since, with no motor-stop. `cyclePos` (UCA-8) the position,
\* in the selected mode's valve order, of the last stroke output switched on in the running
\* work cycle, counted by watching which output comes on (0: no cycle, or the cycle was
\* abandoned by RET, a motor stop or another mode selected; Skipped: an output came on
\* out of that order). `coolDemand` (UCA-10) a temp_high edge came while the motor ran, and
\* since then no temp_ok and the motor has kept running. `runSwitch` (UCA-11) the run-kind
\* switch's position, from the last continuous_on / continuous_off input (single step at
\* power-up): the input's own record, not the reaction's `continuous`.
VARIABLES outputs, continuous, restarted, event, selector, cycleMode, clamped, motorCmd, cyclePos, coolDemand,
          runSwitch
vars == <<chainVars, outputs, continuous, restarted, event, selector, cycleMode, clamped, motorCmd, cyclePos,
          coolDemand, runSwitch>>

\* Observables shared with HydraulicPressFlat (docs/design/hydraulic-press.md §6).
motor == "motor" \in outputs
mode == CHOOSE m \in 1..3 : ModeOf[m] \in active
ActiveStep == {s \in StrokeStates : s \in active}
step == IF ActiveStep = {} THEN "none" ELSE StepNameOf[CHOOSE s \in ActiveStep : TRUE]
\* The analog outputs set by the mode's Pressing / FastAdvance entry, 0 otherwise.
pressure == IF "press_valve" \in outputs THEN Pressure[mode] ELSE 0
speed == IF "fast_valve" \in outputs THEN Speed[mode] ELSE 0
StrokeOn(outs) == outs \cap StrokeOutputs # {}

\* §4: the request the run function of the reacting state makes for input e in mode m,
\* first matching arm wins. Written as actions over the concrete states of mode m (and
\* of each stroke position) rather than as a value <<src, dst>>: the same steps for TLC,
\* but the prover then translates each Request with a constant source and target, whose
\* exit walk is over one known subtree (docs/prove.md, "Cost").
InputMode(e) == CASE e = "mode1" -> 1 [] e = "mode2" -> 2 [] e = "mode3" -> 3 [] OTHER -> 0
NoReaction == /\ log' = <<>> /\ result' = "ok" /\ UNCHANGED <<active, request>>
StepIn(m, k) == k <= Len(StrokeSeq[m]) /\ StepState(m, k) \in active
\* The stroke position k of mode m is done: the next one, after the last Ready (or Feed in
\* continuous operation).
StepFrom(m, k) ==
    IF k < Len(StrokeSeq[m]) THEN Request(StepState(m, k), StepState(m, k + 1))
    ELSE IF continuous THEN Request(StepState(m, k), StepState(m, 2))
    ELSE Request(StepState(m, k), StepState(m, 1))
StepDone(m) ==
    CASE StepIn(m, 1) -> StepFrom(m, 1) [] StepIn(m, 2) -> StepFrom(m, 2) [] StepIn(m, 3) -> StepFrom(m, 3)
      [] StepIn(m, 4) -> StepFrom(m, 4) [] StepIn(m, 5) -> StepFrom(m, 5) [] StepIn(m, 6) -> StepFrom(m, 6)
      [] StepIn(m, 7) -> StepFrom(m, 7) [] StepIn(m, 8) -> StepFrom(m, 8) [] OTHER -> StepFrom(m, 9)
ModeChange(m, e) ==
    CASE InputMode(e) = 1 -> Request(ModeOf[m], ModeOf[1])
      [] InputMode(e) = 2 -> Request(ModeOf[m], ModeOf[2])
      [] OTHER -> Request(ModeOf[m], ModeOf[3])
\* A CASE, not an IF chain: its arms are translated side by side (one path condition each)
\* rather than nested nine deep.
Reaction(e, m) ==
    CASE e = "motor_on" /\ OffOf[m] \in active -> Request(OffOf[m], OnOf[m])
      [] e = "motor_off" /\ OnOf[m] \in active -> Request(OnOf[m], OffOf[m])
      [] InputMode(e) \notin {0, m} -> ModeChange(m, e)
      [] e = "ret" /\ step # "none" -> Request(StrokeOf[m], StrokeOf[m])
      [] e = "start" /\ step = "Ready" -> Request(StepState(m, 1), StepState(m, 2))
      [] e = "step_done" /\ step \notin {"none", "Ready"} -> StepDone(m)
      [] e = "temp_high" /\ CoolIdleOf[m] \in active -> Request(CoolIdleOf[m], CoolingOf[m])
      [] e = "temp_ok" /\ CoolingOf[m] \in active -> Request(CoolingOf[m], CoolIdleOf[m])
      [] OTHER -> NoReaction

ApplyLog(outs, lg) ==
    (outs \ {Out(lg[i].state) : i \in {j \in DOMAIN lg : lg[j].kind = "exit"}})
        \cup ({Out(lg[i].state) : i \in {j \in DOMAIN lg : lg[j].kind = "entry"}} \ {"none"})

Init ==
    /\ ChainInit
    /\ outputs = ApplyLog({}, log)
    /\ continuous = FALSE
    /\ restarted = FALSE
    /\ event = "init"
    /\ selector = 1
    /\ cycleMode = 0
    /\ clamped = FALSE
    /\ motorCmd = FALSE
    /\ cyclePos = 0
    /\ coolDemand = FALSE
    /\ runSwitch = FALSE

Scan(e) ==
    \* exactly one mode state is active (SCH-01): one disjunct applies
    /\ \/ mode = 1 /\ Reaction(e, 1)
       \/ mode = 2 /\ Reaction(e, 2)
       \/ mode = 3 /\ Reaction(e, 3)
    /\ outputs' = ApplyLog(outputs, log')
    /\ continuous' = CASE e = "continuous_on" -> TRUE [] e = "continuous_off" -> FALSE [] OTHER -> continuous
    /\ restarted' = (e = "motor_on" /\ ~motor)
    /\ event' = e
    \* Spelt out, not through InputMode: the property must not share the reaction's decoding.
    /\ selector' = CASE e = "mode1" -> 1 [] e = "mode2" -> 2 [] e = "mode3" -> 3 [] OTHER -> selector
    /\ cycleMode' = IF e = "start" THEN selector' ELSE IF StrokeOn(outputs') THEN cycleMode ELSE 0
    /\ clamped' = IF ~StrokeOn(outputs') \/ "feed_valve" \in outputs' THEN FALSE
                  ELSE clamped \/ "clamp_valve" \in outputs'
    /\ motorCmd' = IF e = "motor_on" THEN TRUE ELSE motorCmd /\ e # "motor_off" /\ "motor" \in outputs'
    /\ cyclePos' =
           LET switched == (outputs' \cap StrokeOutputs) \ outputs
               order == ValveOrder[selector']
           IN IF e \in {"ret", "motor_off"} \/ selector' # selector THEN 0
              ELSE IF switched = {} THEN cyclePos
              ELSE IF switched = {order[1]} /\ cyclePos \in {0, Len(order)} THEN 1
              ELSE IF cyclePos \in 1..(Len(order) - 1) /\ switched = {order[cyclePos + 1]} THEN cyclePos + 1
              ELSE Skipped
    /\ coolDemand' = (("motor" \in outputs') /\ (e = "temp_high" \/ (coolDemand /\ e # "temp_ok")))
    /\ runSwitch' = IF e = "continuous_on" THEN TRUE ELSE IF e = "continuous_off" THEN FALSE ELSE runSwitch

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

\* The hazard properties of docs/design/hydraulic-press.md §7 (UCA-1 .. UCA-7): over the
\* inputs (event, and the history above) and the outputs, across scans.
\* UCA-1: no stroke output unless Start began the work cycle it belongs to: after a
\* motor stop, a RET or a mode change, none until the next Start, whatever sensor edges come.
UCA1_STROKE_ONLY_AFTER_START == StrokeOn(outputs) => cycleMode # 0
\* UCA-2: a motor-stop input switches the motor and every stroke output off in that scan.
UCA2_MOTOR_STOP_SAME_SCAN == event = "motor_off" => ~motor /\ ~StrokeOn(outputs)
\* UCA-3: RET switches every stroke output off in that scan.
UCA3_RET_SAME_SCAN == event = "ret" => ~StrokeOn(outputs)
\* UCA-4: the fast-advance and press valves only after the clamp valve in the same work cycle.
UCA4_PRESS_ONLY_CLAMPED == ("fast_valve" \in outputs \/ "press_valve" \in outputs) => clamped
\* UCA-5: a work cycle runs in the mode (order, pressure, speed) it was started in, and the
\* press is always in the mode last selected, across motor stops and restarts.
UCA5_CYCLE_IN_SELECTED_MODE ==
    /\ mode = selector
    /\ StrokeOn(outputs) => cycleMode = mode
    /\ "press_valve" \in outputs => pressure = Pressure[selector]
    /\ "fast_valve" \in outputs => speed = Speed[selector]
\* UCA-6: the motor runs only after a motor-start with no motor-stop since.
UCA6_MOTOR_ONLY_AFTER_MOTOR_START == motor => motorCmd
\* UCA-7: a stroke output comes on only in a scan with the sensor edge that ends the stroke
\* before it (step_done), or with Start, which energises the feed valve and no other
\* (bound 0 scans: no stroke advances on another input, none is skipped at Start). The
\* outputs switched on in a scan are those of its entry calls (the entry functions set
\* them), which conformance compares with the C++ engine's call log.
SwitchedOn == {Out(log[i].state) : i \in Kinds("entry")} \cap StrokeOutputs
UCA7_ADVANCE_ONLY_ON_SENSOR ==
    /\ SwitchedOn # {} => event \in {"start", "step_done"}
    /\ event = "start" /\ SwitchedOn # {} => outputs \cap StrokeOutputs = {"feed_valve"}

\* UCA-8 (loss L-2): a work cycle runs through each stroke output of its mode's order, in
\* order, and ends only through all of them: a stroke output comes on only as the next of
\* the selected mode's order after the one before it, the feed valve only when no cycle is
\* running or the last one is complete; the stroke outputs go off with no RET, motor stop or
\* mode selection (a cycle ended, not abandoned) only after the mode's last stroke output
\* (bound 0 scans: the scan in which the output comes on or the outputs go off). A skipped
\* eject, blow or scrap stroke leaves the part or the scrap in the die for the next feed.
UCA8_CYCLE_THROUGH_EVERY_STROKE ==
    /\ cyclePos # Skipped
    /\ ~StrokeOn(outputs) => cyclePos \in {0, Len(ValveOrder[selector])}

\* UCA-9 (H-1): the running lamp (the aux chain's, lit by the motor-on state) shows the
\* motor in every scan: never dark while the hydraulics run, never lit with them stopped
\* (bound 0 scans), in every mode.
UCA9_LAMP_SHOWS_MOTOR == ("lamp" \in outputs) <=> motor
\* UCA-10 (H-5): the cooling pump runs from a temp_high edge that comes while the motor
\* runs until a temp_ok edge or the motor stops, in every mode (bound 0 scans).
UCA10_COOLING_ON_DEMAND == coolDemand => "cool_pump" \in outputs

\* UCA-11 (H-1): in single-step operation (the run-kind switch at single step) a new work
\* cycle waits for Start: the feed valve is switched on only in a scan with Start, or in
\* continuous operation by the last stroke's sensor edge (bound 0 scans).
UCA11_SINGLE_STEP_WAITS_FOR_START == "feed_valve" \in SwitchedOn /\ event # "start" => runSwitch

Witness_RestartAfterStroke == ~(restarted /\ mode = 2)  \* INV_PRESS (restart conjunct), UCA-5 across a restart
Witness_MidStroke == step \notin {"Pressing"}          \* INV_PRESS_OUTPUTS_OF_ACTIVE, UCA-4
Witness_Cooling == ~("cool_pump" \in outputs /\ step = "Eject")
Witness_FeedBySensor == ~(event = "step_done" /\ SwitchedOn = {"feed_valve"})  \* UCA-7: continuous operation re-enters Feed on the sensor edge
\* The inputs each behaviour of the press needs reached, so a press that never takes one
\* (never offered, or ignored) loses a witness (docs/mutate.md, "Reachability witnesses"):
\* a cycle of mode 2 and of mode 3 completed through the mode's last stroke (UCA-8), the
\* cooling pump switched off again by temp_ok, the lamp lit with the motor.
Witness_Mode2CycleComplete == ~(selector = 2 /\ cyclePos = 8 /\ ~StrokeOn(outputs))
Witness_Mode3CycleComplete == ~(selector = 3 /\ cyclePos = 6 /\ ~StrokeOn(outputs))
Witness_CoolingStops == ~(event = "temp_ok" /\ "cool_pump" \notin outputs /\ \E i \in Kinds("exit") : Out(log[i].state) = "cool_pump")
Witness_Lamp == ~("lamp" \in outputs)
\* ... a motor stop and a RET that each switch a stroke output off (UCA-2's and UCA-3's
\* situations), a return to mode 1 from another mode, and the run kind switched back to
\* single step during a running cycle.
Witness_MotorStopMidStroke == ~(event = "motor_off" /\ \E i \in Kinds("exit") : Out(log[i].state) \in StrokeOutputs)
Witness_RetMidStroke == ~(event = "ret" /\ \E i \in Kinds("exit") : Out(log[i].state) \in StrokeOutputs)
Witness_BackToMode1 == ~(event = "mode1" /\ log # <<>>)
Witness_SingleStepInCycle == ~(event = "continuous_off" /\ StrokeOn(outputs))
Witness_ModeChangeMidCycle == ~(event = "mode3" /\ Len(log) = 8)  \* UCA-5: a mode change in a running cycle exits the motor-on subtree (6 exits, 2 entries)
===============================================================================
