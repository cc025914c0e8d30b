---------------------------- MODULE WdRejected ----------------------------
(* Unused calls an operator with the wrong number of arguments: the checker *)
(* rejects the module, so it is not provable (the prover never reads Unused).*)
EXTENDS Naturals
VARIABLE x

Double(n) == 2 * n
Unused == Double(x, x)

Init == x = 0
Next == x' = x
TypeOK == x \in 0..1
=============================================================================
