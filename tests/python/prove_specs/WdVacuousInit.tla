--------------------------- MODULE WdVacuousInit ---------------------------
(* Init asks for x = N and x > 5 while the ASSUME keeps N in 1..3: there is *)
(* no initial state, so every invariant "holds" -- for nothing.            *)
EXTENDS Naturals
CONSTANT N
ASSUME N \in 1..3
VARIABLE x

Init == x = N /\ x > 5
Next == x' = x

TypeOK == x \in Nat
Positive == x > 0
=============================================================================
