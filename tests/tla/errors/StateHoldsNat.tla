---- MODULE StateHoldsNat ----
(* Init gives x the value Nat, a set TLC cannot fingerprint: "TLC has     *)
(* found a state in which the value of a variable contains Nat" at line 7 *)
(* (issue 27 item 3), exit 75; 1 state generated, 0 distinct.              *)
EXTENDS Naturals
VARIABLE x
Init == x = Nat
Next == x' = x
====
