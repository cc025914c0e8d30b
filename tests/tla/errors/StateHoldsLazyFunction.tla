---- MODULE StateHoldsLazyFunction ----
(* Next stores a function over Nat in x: TLC fingerprints the new state,  *)
(* which needs the whole function, and fails (exit 75) while generating   *)
(* the successors of the first state, after 2 states generated, 1         *)
(* distinct; ours names the action (line 9) and the infinite domain.      *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = [n \in Nat |-> n + x]
====
