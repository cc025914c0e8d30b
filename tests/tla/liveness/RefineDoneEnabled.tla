-------------------------- MODULE RefineDoneEnabled --------------------------
(* The EWD840 / SyncTerminationDetection pattern: the refinement property   *)
(* D!Spec has WF_vars(Detect) where Detect says done' = TRUE and done is    *)
(* the expression flag = 1 /\ tok = "w".  In ENABLED <<Detect>>_vars TLC   *)
(* binds D's own variable done (getPrimedVar stops at the substitution)    *)
(* instead of evaluating flag' before it has a value.  TLC: success, 8     *)
(* states generated, 5 distinct, depth 3.                                  *)
EXTENDS Naturals
VARIABLES x, flag, tok
vars == <<x, flag, tok>>
done == flag = 1 /\ tok = "w"
Init == x \in 0..2 /\ flag = 0 /\ tok = "b"
Dec == x > 0 /\ x' = x - 1 /\ UNCHANGED <<flag, tok>>
Pass == x = 0 /\ tok = "b" /\ tok' = "w" /\ UNCHANGED <<x, flag>>
Detect == x = 0 /\ tok = "w" /\ flag' = 1 /\ UNCHANGED <<x, tok>>
Next == Dec \/ Pass \/ Detect
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)
D == INSTANCE DoneDetection
DSpec == D!Spec
=============================================================================
