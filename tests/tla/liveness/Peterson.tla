----------------------------- MODULE Peterson -----------------------------
(* Peterson's algorithm for two processes 0 and 1, with weak fairness on  *)
(* each process.  Mutual exclusion holds, and a process that tries gets   *)
(* into its critical section.  Expected: success.                         *)
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
Spec == Init /\ [][Next]_vars /\ \A p \in {0, 1} : WF_vars(Yield(p) \/ Enter(p) \/ Leave(p))

MutualExclusion == ~(pc[0] = "cs" /\ pc[1] = "cs")
Progress == \A p \in {0, 1} : (pc[p] = "set") ~> (pc[p] = "cs")
=============================================================================
