--------------------------- MODULE ConstraintEdge ---------------------------
(***************************************************************************)
(* An edge case of TLC's semantics: invariants are checked on every newly  *)
(* generated successor, including one that a state CONSTRAINT excludes     *)
(* from the model.  Here the constraint keeps n =< 4, and the invariant    *)
(* n =< 4 is violated by the first successor outside the constraint, even  *)
(* though that state is never added to the set of distinct states.         *)
(*                                                                         *)
(* Exercises: CONSTRAINT, \E over a range in an action, an invariant       *)
(* violated by a constrained-out state.  Expected: safety failure of       *)
(* Bounded with a trace ending in n = 5; the reported depth is 5 (the      *)
(* violating state is not part of the explored graph) while the trace has  *)
(* 6 states.                                                               *)
(***************************************************************************)
EXTENDS Naturals

VARIABLES n, parity

Init == n = 0 /\ parity = 0

Next == \E k \in 1..2 : /\ n' = n + 1
                        /\ parity' = (parity + k) % 2

InModel == n <= 4
Bounded == n <= 4
=============================================================================
