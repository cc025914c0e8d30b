---- MODULE LetShadowsVariable ----
(* The LET of Inv defines x, the name of a variable.  SANY: "Operator x    *)
(* already defined or declared." and "Multiply-defined symbol 'x'" at line *)
(* 10, exit 150 (issue 27 item 3); it is never evaluated.                  *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = x
Inv ==
  LET x == 5 IN x < 3
====
