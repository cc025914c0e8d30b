------------------------- MODULE UnknownIdentifier -------------------------
(* Next refers to `limit`, which is declared nowhere (the constant is      *)
(* spelled Limit).  Expected: semantic error at line 12, column 13.        *)
EXTENDS Naturals

CONSTANT Limit

VARIABLE x

Init == x = 0

Next == x < limit /\ x' = x + 1
=============================================================================
