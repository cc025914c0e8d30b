----------------------------- MODULE PetersonNoFair -----------------------------
(* Peterson's algorithm without fairness: a process may stop forever,   *)
(* so Progress fails (the counterexample ends by stuttering).            *)
(* Expected: temporal property violated.                                 *)
EXTENDS Naturals
VARIABLES flag, turn, pc
vars == <<flag, turn, pc>>
Other(p) == 1 - p
Init == flag = [p \in {0, 1} |-> FALSE] /\ turn = 0 /\ pc = [p \in {0, 1} |-> "idle"]

Try(p) == pc[p] = "idle" /\ flag' = [flag EXCEPT ![p] = TRUE] /\ pc' = [pc EXCEPT ![p] = "set"]
          /\ UNCHANGED turn
Yield(p) == pc[p] = "set" /\ turn' = Other(p) /\ pc' = [pc EXCEPT ![p] = "wait"] /\ UNCHANGED flag
Enter(p) == pc[p] = "wait" /\ (~flag[Other(p)] \/ turn = p) /\ pc' = [pc EXCEPT ![p] = "cs"]
            /\ UNCHANGED <<flag, turn>>
Leave(p) == pc[p] = "cs" /\ flag' = [flag EXCEPT ![p] = FALSE] /\ pc' = [pc EXCEPT ![p] = "idle"]
            /\ UNCHANGED turn
Proc(p) == Try(p) \/ Yield(p) \/ Enter(p) \/ Leave(p)
Next == \E p \in {0, 1} : Proc(p)
Spec == Init /\ [][Next]_vars

MutualExclusion == ~(pc[0] = "cs" /\ pc[1] = "cs")
Progress == \A p \in {0, 1} : (pc[p] = "set") ~> (pc[p] = "cs")
=============================================================================
