---- MODULE Latin1Comment ----
(* A module saved in Latin-1: the bytes of "café" and "été" below are not  *)
(* UTF-8.  TLC reads any bytes in comments; so must we.  The cfg gives a   *)
(* value to Unused, a name the spec does not have: TLC ignores it.         *)
(* Expected: success, 3 distinct states, 3 generated, depth 3.            *)
EXTENDS Naturals
VARIABLE x \* café
Init == x = 0 (* été *)
Next == x < 2 /\ x' = x + 1
====
