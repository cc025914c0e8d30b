---- MODULE AssertInInvariant ----
(* An Assert that fails inside an invariant, through an operator: TLC     *)
(* reports "Evaluating invariant Inv failed." (exit 76), with the trace   *)
(* up to the state being checked (x = 3); 4 generated, 4 distinct.       *)
EXTENDS Naturals, TLC
VARIABLE x
Check(v) == Assert(v < 3, "big")
Inv == x < 10 /\ Check(x)
Init == x = 0
Next == x' = x + 1
====
