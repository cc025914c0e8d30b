-------------------------- MODULE PropertyOrderTableau --------------------------
(* PropertyOrder's properties listed B, A, C: TLC checks them in that order    *)
(* (its OrderOfSolutions follow the .cfg; A's group of forms without a tableau  *)
(* sits where A is), so it reports B's counterexample 0, 1, stuttering, which  *)
(* also violates C; A's nearer one (stuttering at 0) is not reached.           *)
(* Expected (TLC 1.8.0): "Temporal properties B and C were violated."         *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 3
Spec == Init /\ [][Next]_x

A == []<>(x = 1)
B == (x = 1) ~> (x = 2)
C == <>(x = 5)
=============================================================================
