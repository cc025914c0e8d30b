------------------------- MODULE UseBeforeDefinition -------------------------
(* Inv uses Bound, which is defined only after it; TLA+ requires a symbol *)
(* to be defined before use.  Expected: semantic error at line 9, column 14 *)
(* (exit 150).                                                             *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Inv == x \in Bound
Bound == {0, 1}
=============================================================================
