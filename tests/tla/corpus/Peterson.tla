------------------------------ MODULE Peterson ------------------------------
(***************************************************************************)
(* Peterson's mutual-exclusion algorithm for two processes, 0 and 1, with  *)
(* each atomic step of the usual pseudo-code as one action:                *)
(*                                                                         *)
(*   idle:    flag[p] := TRUE                                              *)
(*   setturn: turn := other                                                *)
(*   wait:    await ~flag[other] \/ turn = p                               *)
(*   cs:      flag[p] := FALSE, back to idle                               *)
(*                                                                         *)
(* Exercises: functions [p \in S |-> e], EXCEPT, string-valued program     *)
(* counters, \E p \in S over a disjunction of parameterised actions,       *)
(* ENABLED inside an invariant (the algorithm never gets stuck).           *)
(* Expected: success.                                                      *)
(***************************************************************************)
EXTENDS Naturals

VARIABLES flag, turn, pc

vars == <<flag, turn, pc>>

Procs == {0, 1}

Other(p) == 1 - p

TypeOK ==
    /\ flag \in [Procs -> BOOLEAN]
    /\ turn \in Procs
    /\ pc \in [Procs -> {"idle", "setturn", "wait", "cs"}]

Init ==
    /\ flag = [p \in Procs |-> FALSE]
    /\ turn \in Procs
    /\ pc = [p \in Procs |-> "idle"]

SetFlag(p) ==
    /\ pc[p] = "idle"
    /\ flag' = [flag EXCEPT ![p] = TRUE]
    /\ pc' = [pc EXCEPT ![p] = "setturn"]
    /\ UNCHANGED turn

SetTurn(p) ==
    /\ pc[p] = "setturn"
    /\ turn' = Other(p)
    /\ pc' = [pc EXCEPT ![p] = "wait"]
    /\ UNCHANGED flag

Enter(p) ==
    /\ pc[p] = "wait"
    /\ \/ ~flag[Other(p)]
       \/ turn = p
    /\ pc' = [pc EXCEPT ![p] = "cs"]
    /\ UNCHANGED <<flag, turn>>

Leave(p) ==
    /\ pc[p] = "cs"
    /\ flag' = [flag EXCEPT ![p] = FALSE]
    /\ pc' = [pc EXCEPT ![p] = "idle"]
    /\ UNCHANGED turn

Next == \E p \in Procs : SetFlag(p) \/ SetTurn(p) \/ Enter(p) \/ Leave(p)

Spec == Init /\ [][Next]_vars

MutualExclusion == ~ (pc[0] = "cs" /\ pc[1] = "cs")

\* Some process can always take a step.
NeverStuck == ENABLED Next
=============================================================================
