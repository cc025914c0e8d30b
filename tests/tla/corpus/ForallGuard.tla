------------------------------ MODULE ForallGuard ------------------------------
(***************************************************************************)
(* Minimised by the differential tester (seed 3, spec 980, grammar 2): a  *)
(* guard \A a \in 0..1 : \E e \in 0..2 : e < 3 before the assignment is  *)
(* 2 x 3 conjunct branches, 9 successors per state in TLC.                 *)
(* Expected: success, 2 distinct states, 19 generated, depth 2.           *)
(***************************************************************************)
EXTENDS Naturals, Sequences, FiniteSets
VARIABLES v0
Init ==
    /\ v0 = {}
A1 ==
    /\ (\A a2 \in (0..(1 % 3)) : (\E e3 \in 0..2 : (e3 < 3)))
    /\ LET n4 == (DOMAIN [k5 \in {1, 2} |-> (k5) % 3] \ {2}) IN v0' = n4
Next ==
    \/ A1
=============================================================================
