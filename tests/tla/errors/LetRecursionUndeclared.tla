---- MODULE LetRecursionUndeclared ----
(* The LET operator f calls itself without a RECURSIVE declaration: SANY   *)
(* makes a LET definition visible only after it, so f in its own body is   *)
(* "Unknown operator: `f'." at line 10, exit 150 (issue 27 item 3).        *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = x
Inv == LET f(n) ==
             IF n = 0 THEN 0 ELSE f(n - 1)
       IN f(3) = 0
====
