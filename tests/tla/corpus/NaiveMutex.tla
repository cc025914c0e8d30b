----------------------------- MODULE NaiveMutex -----------------------------
(***************************************************************************)
(* A broken lock: each process first checks that no other process has      *)
(* raised its flag, and only then raises its own.  Between the check and   *)
(* the raise another process can do the same, so two processes can end up  *)
(* in the critical section together.                                       *)
(*                                                                         *)
(* Exercises: a CONSTANT number of processes, functions over 1..N,         *)
(* EXCEPT updating two functions in one step, \A/\E nested in a guard, a   *)
(* mutual-exclusion invariant over pairs.  Expected: safety failure of     *)
(* MutualExclusion.                                                        *)
(***************************************************************************)
EXTENDS Naturals

CONSTANT N

Procs == 1..N

VARIABLES flag, pc

Init == flag = [p \in Procs |-> FALSE] /\ pc = [p \in Procs |-> "check"]

Check(p) ==
    /\ pc[p] = "check"
    /\ \A q \in Procs \ {p} : ~flag[q]
    /\ pc' = [pc EXCEPT ![p] = "raise"]
    /\ UNCHANGED flag

Raise(p) ==
    /\ pc[p] = "raise"
    /\ flag' = [flag EXCEPT ![p] = TRUE]
    /\ pc' = [pc EXCEPT ![p] = "cs"]

Exit(p) ==
    /\ pc[p] = "cs"
    /\ flag' = [flag EXCEPT ![p] = FALSE]
    /\ pc' = [pc EXCEPT ![p] = "check"]

Next == \E p \in Procs : Check(p) \/ Raise(p) \/ Exit(p)

MutualExclusion == \A p, q \in Procs : (p /= q) => ~(pc[p] = "cs" /\ pc[q] = "cs")
=============================================================================
