----------------------------- MODULE RealNumber -----------------------------
(* A real-number literal.  SANY parses 1.5 (it is TLA+ syntax for an       *)
(* element of Real), but TLC does not implement the reals.  Expected:      *)
(* TLC refuses it; see expected.json for what exactly happens.             *)
EXTENDS Naturals

VARIABLE x

Init == x = 0

Next == x' = x + 1.5
=============================================================================
