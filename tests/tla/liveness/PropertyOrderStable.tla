-------------------------- MODULE PropertyOrderStable --------------------------
(* Stable (<>[]P) listed first: its negation []<>~P is moved to the end of     *)
(* TLC's DNF (LNDisj.toDNF merges []<>A disjuncts last), so TLC checks Reach   *)
(* first and reports its counterexample, stuttering at 0, which Stable allows. *)
(* Expected (TLC 1.8.0): "Temporal property Reach was violated."              *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x

Stable == <>[](x = 0)
Reach == <>(x = 5)
=============================================================================
