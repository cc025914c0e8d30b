----------------------------- MODULE HeadOfEmpty -----------------------------
(* Head of the empty sequence while computing a successor: TLC reports the  *)
(* Sequences module's own error and exits with 255 (in Init it is 75, in an *)
(* invariant 76, like any evaluation error).                                *)
EXTENDS Sequences
VARIABLE q
Init == q = <<1>>
Next == q' = Tail(q) /\ Head(q') = 1
=============================================================================
