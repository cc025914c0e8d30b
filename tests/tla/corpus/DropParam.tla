------------------------------ MODULE DropParam ------------------------------
(***************************************************************************)
(* The user's report (issue 14): an operator parameter that stands for a   *)
(* state variable is primed and assigned, q' = ..., with q bound to a or   *)
(* b.  Both actions must be found, not silently lost.                      *)
(*                                                                         *)
(* Exercises: q' = e with q an operator parameter, \E inside the operator, *)
(* a function constructor over 1..Len(q)-1, UNCHANGED, CHECK_DEADLOCK      *)
(* FALSE (both sequences end empty).                                       *)
(* Expected: success, 32 distinct states, 81 generated, depth 6.          *)
(***************************************************************************)
EXTENDS Naturals, Sequences
VARIABLES a, b
Init == a = <<1,2,3>> /\ b = <<4,5>>
Drop(q) == /\ q # <<>>
           /\ \E i \in 1..Len(q) : q' = [j \in 1..(Len(q)-1) |-> IF j < i THEN q[j] ELSE q[j+1]]
Next == (Drop(a) /\ UNCHANGED b) \/ (Drop(b) /\ UNCHANGED a)
=============================================================================
