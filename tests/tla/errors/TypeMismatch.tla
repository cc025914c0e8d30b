--------------------------- MODULE TypeMismatch ---------------------------
(* Adding a string to an integer.  SANY accepts it (TLA+ is untyped); TLC  *)
(* fails when it evaluates the sum in the first step from the initial      *)
(* state.  Expected: evaluation error at line 11.                          *)
EXTENDS Naturals

VARIABLE x

Init == x = 0

Next == x' = x + "a"
=============================================================================
