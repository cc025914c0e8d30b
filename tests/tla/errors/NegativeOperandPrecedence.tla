---- MODULE NegativeOperandPrecedence ----
(* 7 \div -2: a prefix minus (precedence 12) as the right operand of an   *)
(* operator that binds tighter (\div, *, ^, \o) needs parentheses; SANY:   *)
(* a parse error at line 8 (issue 27 item 3), exit 150.  2 + -3 is fine.   *)
EXTENDS Integers
VARIABLE x
Init ==
  x = 7 \div -2 + (2 + -3)
Next == x' = x
====
