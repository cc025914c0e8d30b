---------------------------- MODULE Peterson ----------------------------
(* Peterson's mutual exclusion for two processes, in the style of the     *)
(* published pc-based versions.  Constructs: functions over 0..1, EXCEPT, *)
(* CASE on the program counter, \E over processes.  TLC: success.         *)
EXTENDS Naturals
VARIABLES flag, turn, pc
vars == <<flag, turn, pc>>
Other(p) == 1 - p
Init == /\ flag = [p \in 0..1 |-> FALSE]
        /\ turn = 0
        /\ pc = [p \in 0..1 |-> "idle"]
SetFlag(p) == /\ pc[p] = "idle"
              /\ flag' = [flag EXCEPT ![p] = TRUE]
              /\ pc' = [pc EXCEPT ![p] = "turn"]
              /\ UNCHANGED turn
GiveTurn(p) == /\ pc[p] = "turn"
               /\ turn' = Other(p)
               /\ pc' = [pc EXCEPT ![p] = "wait"]
               /\ UNCHANGED flag
Wait(p) == /\ pc[p] = "wait"
           /\ (~flag[Other(p)] \/ turn = p)
           /\ pc' = [pc EXCEPT ![p] = "cs"]
           /\ UNCHANGED <<flag, turn>>
Exit(p) == /\ pc[p] = "cs"
           /\ flag' = [flag EXCEPT ![p] = FALSE]
           /\ pc' = [pc EXCEPT ![p] = "idle"]
           /\ UNCHANGED turn
Next == \E p \in 0..1 : SetFlag(p) \/ GiveTurn(p) \/ Wait(p) \/ Exit(p)
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)
TypeOK == /\ flag \in [0..1 -> BOOLEAN]
          /\ turn \in 0..1
          /\ pc \in [0..1 -> {"idle", "turn", "wait", "cs"}]
MutualExclusion == ~(pc[0] = "cs" /\ pc[1] = "cs")
=============================================================================
