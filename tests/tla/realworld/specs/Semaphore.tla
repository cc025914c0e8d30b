----------------------------- MODULE Semaphore -----------------------------
(* Two processes taking two binary semaphores in opposite orders: the     *)
(* classic deadlock.  Constructs: tuples as program text, functions of    *)
(* records, UNCHANGED of a tuple definition.  TLC: Deadlock reached.      *)
EXTENDS Naturals
VARIABLES sem, pc
vars == <<sem, pc>>
Order == [p \in {"A", "B"} |-> IF p = "A" THEN <<"s1", "s2">> ELSE <<"s2", "s1">>]
Init == sem = [s \in {"s1", "s2"} |-> 1] /\ pc = [p \in {"A", "B"} |-> 1]
Take(p) == /\ pc[p] \in 1..2
           /\ LET s == Order[p][pc[p]] IN
                /\ sem[s] = 1
                /\ sem' = [sem EXCEPT ![s] = 0]
           /\ pc' = [pc EXCEPT ![p] = @ + 1]
Release(p) == /\ pc[p] = 3
              /\ sem' = [s \in DOMAIN sem |-> 1]
              /\ pc' = [pc EXCEPT ![p] = 1]
Next == \E p \in {"A", "B"} : Take(p) \/ Release(p)
Spec == Init /\ [][Next]_vars
=============================================================================
