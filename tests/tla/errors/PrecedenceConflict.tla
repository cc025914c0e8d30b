------------------------- MODULE PrecedenceConflict -------------------------
(* `*` and `\div` have the same precedence but are different operators,    *)
(* so TLA+ requires parentheses: a * b \div c is a syntax error.           *)
(* Expected: parse error (precedence conflict) at line 11.                 *)
EXTENDS Naturals

VARIABLE x

Init == x = 0

Next == x' = x * 3 \div 2
=============================================================================
