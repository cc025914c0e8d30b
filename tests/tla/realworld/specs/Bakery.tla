----------------------------- MODULE Bakery -----------------------------
(* Lamport's bakery algorithm for N processes with tickets bounded by a   *)
(* state constraint.  Constructs: CONSTANT N, functions, \A inside a      *)
(* guard, lexicographic comparison via a user operator, CONSTRAINT.       *)
(* TLC: success.                                                          *)
EXTENDS Naturals
CONSTANTS N, MaxTicket
Procs == 1..N
VARIABLES num, flag, pc, unchecked
vars == <<num, flag, pc, unchecked>>
LL(a, b) == \/ num[a] < num[b]
            \/ num[a] = num[b] /\ a < b
Max(S) == IF S = {} THEN 0 ELSE CHOOSE m \in S : \A x \in S : x <= m
Init == /\ num = [p \in Procs |-> 0]
        /\ flag = [p \in Procs |-> FALSE]
        /\ pc = [p \in Procs |-> "ncs"]
        /\ unchecked = [p \in Procs |-> {}]
Enter(p) == /\ pc[p] = "ncs"
            /\ flag' = [flag EXCEPT ![p] = TRUE]
            /\ pc' = [pc EXCEPT ![p] = "choose"]
            /\ UNCHANGED <<num, unchecked>>
Choose(p) == /\ pc[p] = "choose"
             /\ num' = [num EXCEPT ![p] = 1 + Max({num[q] : q \in Procs})]
             /\ flag' = [flag EXCEPT ![p] = FALSE]
             /\ unchecked' = [unchecked EXCEPT ![p] = Procs \ {p}]
             /\ pc' = [pc EXCEPT ![p] = "wait"]
Wait(p) == /\ pc[p] = "wait"
           /\ \/ /\ unchecked[p] # {}
                 /\ \E q \in unchecked[p] :
                       /\ ~flag[q]
                       /\ num[q] = 0 \/ LL(p, q)
                       /\ unchecked' = [unchecked EXCEPT ![p] = @ \ {q}]
                 /\ UNCHANGED <<num, flag, pc>>
              \/ /\ unchecked[p] = {}
                 /\ pc' = [pc EXCEPT ![p] = "cs"]
                 /\ UNCHANGED <<num, flag, unchecked>>
Exit(p) == /\ pc[p] = "cs"
           /\ num' = [num EXCEPT ![p] = 0]
           /\ pc' = [pc EXCEPT ![p] = "ncs"]
           /\ UNCHANGED <<flag, unchecked>>
Next == \E p \in Procs : Enter(p) \/ Choose(p) \/ Wait(p) \/ Exit(p)
Spec == Init /\ [][Next]_vars
Bound == \A p \in Procs : num[p] <= MaxTicket
MutualExclusion == \A p, q \in Procs : p # q => ~(pc[p] = "cs" /\ pc[q] = "cs")
=============================================================================
