------------------------- MODULE DuplicateDefinition -------------------------
(* Inv is defined twice.  Expected: semantic error at the second          *)
(* definition, line 9 (exit 150).                                          *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Inv == x <= 3
Inv == x >= 0
=============================================================================
