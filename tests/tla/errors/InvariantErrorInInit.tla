---- MODULE InvariantErrorInInit ----
(* An invariant that fails to evaluate in the initial state: TLC reports *)
(* the error itself "While working on the initial state" (exit 75, 1     *)
(* state generated, 1 distinct).  (SUBSET 0)..2: SUBSET binds tighter.   *)
(* Found by the differential tester (seed 3, spec 1349).                 *)
EXTENDS Naturals, FiniteSets
VARIABLE x
Init == x = 0
Next == x' = x
Inv == \E t \in SUBSET 0..2 : Cardinality(t) = 0
====
