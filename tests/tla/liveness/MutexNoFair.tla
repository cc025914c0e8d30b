---------------------------- MODULE MutexNoFair ----------------------------
(* Two processes share a lock.  Without fairness a behaviour may stutter   *)
(* forever in the initial state, so "someone eventually enters" fails.     *)
(* Expected: temporal property violated; lasso = initial state + stutter. *)
EXTENDS Naturals
CONSTANT Procs
VARIABLES pc, lock
vars == <<pc, lock>>

Init == pc = [p \in Procs |-> "idle"] /\ lock = FALSE

Request(p) == pc[p] = "idle" /\ pc' = [pc EXCEPT ![p] = "wait"] /\ UNCHANGED lock
Enter(p) == pc[p] = "wait" /\ ~lock /\ lock' = TRUE /\ pc' = [pc EXCEPT ![p] = "cs"]
Exit(p) == pc[p] = "cs" /\ lock' = FALSE /\ pc' = [pc EXCEPT ![p] = "idle"]

Next == \E p \in Procs : Request(p) \/ Enter(p) \/ Exit(p)
Spec == Init /\ [][Next]_vars

MutualExclusion == \A p, q \in Procs : p /= q => ~(pc[p] = "cs" /\ pc[q] = "cs")
SomeoneEnters == <>(\E p \in Procs : pc[p] = "cs")
=============================================================================
