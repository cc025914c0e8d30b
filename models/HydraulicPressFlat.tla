-------------------------- MODULE HydraulicPressFlat --------------------------
(* DEFECTIVE REFERENCE: the document's flat switch-case press program, bug   *)
(* included (docs/design/hydraulic-press.md §5). Motor-off does not reset    *)
(* the stroke variable Cur_Runing (`cur`), so a motor restart resumes the    *)
(* stroke where it stopped. `safestate check` must find INV_PRESS violated.  *)
EXTENDS Naturals

StepNames == <<"Ready", "Feed", "Locate", "Clamp", "FastAdvance", "Pressing", "Blow", "Eject", "ClearScrap">>
Valves == <<"none", "feed_valve", "locate_valve", "clamp_valve", "fast_valve", "press_valve", "blow_valve", "eject_valve", "scrap_valve">>
StrokeOutputs == {Valves[k] : k \in 2..9}
Inputs == {"motor_on", "motor_off", "start", "ret", "step_done", "mode1", "mode2", "mode3",
           "continuous_on", "continuous_off", "temp_high", "temp_ok"}
InputMode(e) == CASE e = "mode1" -> 1 [] e = "mode2" -> 2 [] e = "mode3" -> 3 [] OTHER -> 0

VARIABLES
    MoToOut,     \* motor output (document name)
    cur,         \* Cur_Runing: 0 = ready, 1 = feed .. 8 = clear scrap
    FangShi,     \* operating mode 1..3
    continuous,  \* run-kind switch
    outputs, restarted, event
vars == <<MoToOut, cur, FangShi, continuous, outputs, restarted, event>>

\* Observables shared with HydraulicPress (design page §6).
motor == MoToOut
mode == FangShi
step == StepNames[cur + 1]

\* The switch (Cur_Runing) of one mode; the three modes share it (design §3).
Switch(c, e) ==
    CASE e = "ret" -> 0
      [] c = 0 /\ e = "start" -> 1
      [] c \in 1..7 /\ e = "step_done" -> c + 1
      [] c = 8 /\ e = "step_done" -> IF continuous THEN 1 ELSE 0
      [] OTHER -> c

\* Output stage at the end of the scan: the valve of the current stroke while
\* the motor runs. Lighting and cooling are not in the document's flat excerpt.
OutputStage(m, c) == IF m THEN {"motor"} \cup ({Valves[c + 1]} \ {"none"}) ELSE {}

Init ==
    /\ MoToOut = FALSE
    /\ cur = 0
    /\ FangShi = 1
    /\ continuous = FALSE
    /\ outputs = {}
    /\ restarted = FALSE
    /\ event = "init"

Scan(e) ==
    LET m1 == IF e = "motor_on" THEN TRUE ELSE MoToOut   \* if(MON==true) MoToOut=1;
        m == IF e = "motor_off" THEN FALSE ELSE m1       \* if(MOFF==true) MoToOut=0;
        c == IF m THEN Switch(cur, e) ELSE cur           \* if(MoToOut==1) switch ... (no else: the bug)
    IN /\ MoToOut' = m
       /\ cur' = c
       /\ FangShi' = IF m /\ InputMode(e) # 0 THEN InputMode(e) ELSE FangShi
       /\ continuous' = CASE e = "continuous_on" -> TRUE [] e = "continuous_off" -> FALSE [] OTHER -> continuous
       /\ outputs' = OutputStage(m, c)
       /\ restarted' = (e = "motor_on" /\ ~MoToOut)
       /\ event' = e

Next == \E e \in Inputs : Scan(e)

Spec == Init /\ [][Next]_vars

\* SCH-05: every variable of the flat press in its type: motor bit, step counter 0..8,
\* mode 1..3, the outputs the motor and the stroke valves.
TypeOK ==
    /\ MoToOut \in BOOLEAN /\ cur \in 0..8 /\ FangShi \in 1..3 /\ continuous \in BOOLEAN
    /\ outputs \subseteq {"motor"} \cup StrokeOutputs
    /\ restarted \in BOOLEAN /\ event \in Inputs \cup {"init"}

\* SCH-05 INV-PRESS (same text as HydraulicPress.tla): violated here.
INV_PRESS ==
    /\ ~motor => outputs \cap StrokeOutputs = {}
    /\ restarted => step = "Ready" /\ outputs \cap StrokeOutputs = {}
===============================================================================
