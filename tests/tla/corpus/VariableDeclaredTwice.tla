---- MODULE VariableDeclaredTwice ----
(***************************************************************************)
(* x is declared twice (issue 27 item 4).  SANY only warns ("Multiple       *)
(* declarations or definitions for symbol x.") and TLC checks the module    *)
(* with one variable x: no error, 3 states generated, 2 distinct, depth 2.  *)
(***************************************************************************)
EXTENDS Naturals
VARIABLE x
VARIABLE x
Init == x = 0
Next == x' = 1 - x
====
