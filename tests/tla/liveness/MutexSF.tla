------------------------------ MODULE MutexSF ------------------------------
(* The lock of MutexNoFair with STRONG fairness on Enter(p): Enter(p) is   *)
(* enabled infinitely often while p waits, so p eventually enters.        *)
(* Expected: success.                                                    *)
EXTENDS Naturals
CONSTANT Procs
VARIABLES pc, lock
vars == <<pc, lock>>

Init == pc = [p \in Procs |-> "idle"] /\ lock = FALSE

Request(p) == pc[p] = "idle" /\ pc' = [pc EXCEPT ![p] = "wait"] /\ UNCHANGED lock
Enter(p) == pc[p] = "wait" /\ ~lock /\ lock' = TRUE /\ pc' = [pc EXCEPT ![p] = "cs"]
Exit(p) == pc[p] = "cs" /\ lock' = FALSE /\ pc' = [pc EXCEPT ![p] = "idle"]

Next == \E p \in Procs : Request(p) \/ Enter(p) \/ Exit(p)
Fairness == \A p \in Procs : SF_vars(Enter(p)) /\ WF_vars(Exit(p))
Spec == Init /\ [][Next]_vars /\ Fairness

NoStarvation == \A p \in Procs : (pc[p] = "wait") ~> (pc[p] = "cs")
=============================================================================
