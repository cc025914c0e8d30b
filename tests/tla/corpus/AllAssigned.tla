------------------------------ MODULE AllAssigned ------------------------------
(***************************************************************************)
(* Once every variable of the successor has a value, TLC evaluates the    *)
(* remaining conjuncts as booleans (Tool.getNextStatesAllAssigned): the    *)
(* disjunction (v2 \/ v2) after the assignments gives one successor, not  *)
(* two.  Minimised by the differential tester (seed 1, spec 10: 46 states *)
(* generated instead of TLC's 42).                                         *)
(* Expected: success, 10 distinct states, 12 generated, depth 2.          *)
(***************************************************************************)
EXTENDS Naturals, Sequences, FiniteSets
VARIABLES v0, v1, v2
Keep(x) == UNCHANGED x
Init ==
    /\ v0 \in {{}, {1}}
    /\ v1 \in {{}, {1}}
    /\ v2 \in BOOLEAN
A2 ==
    /\ LET n7 == (0..(2 % 3)) IN v0' = n7
    /\ Keep(v1)
    /\ v2' = (<<0 % 3>> = <<1>>)
    /\ (v2 \/ v2)
Next == A2
=============================================================================
