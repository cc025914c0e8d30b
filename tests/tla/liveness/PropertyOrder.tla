--------------------------- MODULE PropertyOrder ---------------------------
(* Which of several violated properties TLC reports: it checks them in .cfg *)
(* order (A's group of forms without a tableau first here, then B, then C),  *)
(* the counterexample nearest the initial state; the message names each one  *)
(* counterexample violates.  No fairness: x may stutter anywhere.  Here     *)
(* stuttering at x = 0 violates C and A, while B's needs a step first.      *)
(* Expected (TLC 1.8.0): "Temporal properties A and C were violated."      *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 3
Spec == Init /\ [][Next]_x

A == []<>(x = 1)
B == (x = 1) ~> (x = 2)
C == <>(x = 5)
=============================================================================
