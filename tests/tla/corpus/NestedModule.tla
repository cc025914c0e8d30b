---- MODULE NestedModule ----
(***************************************************************************)
(* A module nested in another sees what the enclosing module EXTENDS and   *)
(* defines before it (issue 27 item 4: "Unknown operator `+'" before):      *)
(* Inner uses Naturals' + and %, and Limit, and is instanced as I.          *)
(* TLC: no error, 4 states generated, 3 distinct, depth 3.                  *)
(***************************************************************************)
EXTENDS Naturals
VARIABLE x
Limit == 3
---- MODULE Inner ----
Succ(a) == (a + 1) % Limit
====
I == INSTANCE Inner
Init == x = 0
Next == x' = I!Succ(x)
====
