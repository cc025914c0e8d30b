-------------------------- MODULE RefineDoneLazy -----------------------------
(* RefineDoneEnabled without its Detect step: once x = 0 and the token is  *)
(* white, D!Detect stays enabled (done' = TRUE binds D's own variable done) *)
(* and is never taken, so D!Spec's WF_vars(Detect) is violated.  TLC:      *)
(* exit 13, 6 states generated, 4 distinct, depth 2.                       *)
EXTENDS Naturals
VARIABLES x, flag, tok
vars == <<x, flag, tok>>
done == flag = 1 /\ tok = "w"
Init == x \in 0..2 /\ flag = 0 /\ tok = "b"
Dec == x > 0 /\ x' = x - 1 /\ UNCHANGED <<flag, tok>>
Pass == x = 0 /\ tok = "b" /\ tok' = "w" /\ UNCHANGED <<x, flag>>
Detect == x = 0 /\ tok = "w" /\ flag' = 1 /\ UNCHANGED <<x, tok>>
Next == Dec \/ Pass
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)
D == INSTANCE DoneDetection
DSpec == D!Spec
=============================================================================
