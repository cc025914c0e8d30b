------------------------- MODULE PercentPrecedence -------------------------
(* `+` (precedence 10-10) and `%` (10-11) overlap, so x + x % 2 needs      *)
(* parentheses and is a syntax error.  A curiosity of TLC: SANY's message  *)
(* for this conflict contains a '%' and crashes its own message            *)
(* formatting, so TLC reports a Java exception instead of the conflict.    *)
(* Expected: parse error at line 12.                                       *)
EXTENDS Naturals

VARIABLE x

Init == x = 0
Next == x' = x + x % 2
=============================================================================
