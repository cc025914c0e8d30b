---------------------------- MODULE Counter ----------------------------
(* A counter that wraps at a symbolic bound: proved for every Bound by  *)
(* 1-induction, since TypeOK's domain 0..Bound is itself inductive.     *)
EXTENDS Naturals
CONSTANT Bound
ASSUME Bound \in Nat \ {0}
VARIABLE x, mode

Init == x = 0 /\ mode = "up"
Next == \/ /\ x < Bound /\ x' = x + 1 /\ UNCHANGED mode
        \/ /\ x = Bound /\ x' = 0 /\ mode' = IF mode = "up" THEN "down" ELSE "up"

TypeOK == x \in 0..Bound /\ mode \in {"up", "down"}
Bounded == x <= Bound
=========================================================================
