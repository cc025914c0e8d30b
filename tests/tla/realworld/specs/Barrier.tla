------------------------------ MODULE Barrier ------------------------------
(* A cyclic barrier: every process arrives, then all leave together.     *)
(* The step that releases everybody is \A p \in P : Leave(p), a           *)
(* conjunction of actions over a set (TLC takes p1, pn, ..., p2), and     *)
(* each process may leave to one of two places (the instances branch).   *)
(* TLC: success.                                                          *)
EXTENDS Naturals
CONSTANT P
VARIABLES pc, round
Init == pc = [p \in P |-> "run"] /\ round = 0
Arrive(p) == /\ pc[p] = "run"
             /\ pc' = [pc EXCEPT ![p] = "wait"]
             /\ UNCHANGED round
Leave(p) == \/ pc'[p] = "run"
            \/ pc'[p] = "rest"
Release == /\ \A p \in P : pc[p] = "wait"
           /\ pc' \in [P -> {"run", "rest", "wait"}]
           /\ \A p \in P : Leave(p)
           /\ round' = (round + 1) % 3
Wake(p) == /\ pc[p] = "rest"
           /\ pc' = [pc EXCEPT ![p] = "run"]
           /\ UNCHANGED round
Next == Release \/ \E p \in P : Arrive(p) \/ Wake(p)
NoOneLeftBehind == round > 0 => \E p \in P : pc[p] # "wait" \/ TRUE
=============================================================================
