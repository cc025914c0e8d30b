------------------------- MODULE HydraulicPressProofs -------------------------
(* Proof typing of HydraulicPress for `safestate prove` (proofs/README.md).    *)
(* The model's TypeOK types the chain's active set; the prover also needs the  *)
(* call log (at most 7 calls in one step: motor off exits MotorOn, Stroke, the *)
(* mode, its step, Aux and its cooling state and enters MotorOff), the         *)
(* outputs and the run-kind and restart flags. `event` stays untracked: it is  *)
(* written, never read.                                                        *)
EXTENDS HydraulicPress

LogEvents == [kind : {"entry", "exit", "run"}, state : States]
ProofTypeOK ==
    /\ TypeOK
    /\ log \in Seq(LogEvents)
    /\ Len(log) <= 7
    /\ outputs \subseteq {"motor", "lamp", "cool_pump"} \cup StrokeOutputs
    /\ continuous \in BOOLEAN
    /\ restarted \in BOOLEAN

\* The shape of the active set (SCH-01, SCH-03) and the outputs of the active
\* states (SCH-05): INV_PRESS follows from these (motor off means MotorOn and
\* every stroke state inactive), and together they are 1-inductive.
Strengthen_PRESS ==
    /\ INV_SCH01_ROOT_ACTIVE
    /\ INV_SCH01_PARENT_ACTIVE
    /\ INV_SCH01_ONE_LEAF
    /\ INV_SCH03_PARALLEL
    /\ INV_PRESS_OUTPUTS_OF_ACTIVE
===============================================================================
