---------------------------- MODULE WdDivision ----------------------------
(* 3 \div x with x = 0 in the initial state: Next is ill-defined at once   *)
(* (before, the prover reported a counterexample with x = -1).             *)
EXTENDS Integers
VARIABLE x

Init == x = 0
Next == x' = 3 \div x

TypeOK == x \in Int
NonNegative == x >= 0
=============================================================================
