------------------------- MODULE HydraulicPressProofs -------------------------
(* Proof typing of HydraulicPress for `safestate prove` (proofs/README.md).    *)
(* The model's TypeOK types the chain's active set; the prover also needs the  *)
(* call log (at most 8 calls in one step: a mode change with the motor on     *)
(* exits the cooling state, Aux, the stroke state, Stroke, MX_On and the mode, *)
(* and enters the new mode and its MX_Off), the outputs, the run-kind and      *)
(* restart flags and the hazard properties' history variables.                 *)
EXTENDS HydraulicPress

LogEvents == [kind : {"entry", "exit", "run"}, state : States]
ProofTypeOK ==
    /\ TypeOK
    /\ log \in Seq(LogEvents)
    /\ Len(log) <= 8
    /\ outputs \subseteq {"motor", "lamp", "cool_pump"} \cup StrokeOutputs
    /\ continuous \in BOOLEAN
    /\ restarted \in BOOLEAN
    /\ event \in Inputs \cup {"init"}
    /\ selector \in 1..3
    /\ cycleMode \in 0..3
    /\ clamped \in BOOLEAN
    /\ motorCmd \in BOOLEAN
    /\ cyclePos \in 0..Skipped
    /\ coolDemand \in BOOLEAN
    /\ runSwitch \in BOOLEAN

\* The shape of the active set (SCH-01, SCH-03) and the outputs of the active
\* states (SCH-05): INV_PRESS follows from these (motor off means MX_On and
\* every stroke state inactive). UCA-4's history flag is the position in the
\* work cycle: the clamp stroke is the fourth of every mode's order, so
\* `clamped` holds exactly past it. UCA-8's observer is the stroke position: at
\* the k-th state of the mode's stroke order (Ready first) it has counted k - 1
\* outputs of the mode's valve order; with no stroke state active, none (no cycle, or
\* one abandoned) or all of them (the last cycle complete). UCA-10's observer is
\* the cooling state: a temp_high edge with the motor running enters it, temp_ok and
\* the motor stop leave it. UCA-11's observer is the reaction's run-kind latch. Together
\* with the invariants proved jointly (UCA-1 .. UCA-11 among them) they are 1-inductive.
Strengthen_PRESS ==
    /\ INV_SCH01_ROOT_ACTIVE
    /\ INV_SCH01_PARENT_ACTIVE
    /\ INV_SCH01_ONE_LEAF
    /\ INV_SCH03_PARALLEL
    /\ INV_PRESS_OUTPUTS_OF_ACTIVE
    /\ clamped <=> step \notin {"none", "Ready", "Feed", "Locate"}
    /\ \A m \in 1..3 : \A k \in 2..9 : k <= Len(StrokeSeq[m]) /\ StrokeSeq[m][k] \in active => cyclePos = k - 1
    /\ step \in {"none", "Ready"} => cyclePos \in {0, Len(ValveOrder[selector])}
    /\ coolDemand <=> \E m \in 1..3 : CoolingOf[m] \in active
    /\ runSwitch = continuous
===============================================================================
