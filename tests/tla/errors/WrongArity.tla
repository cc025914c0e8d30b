---------------------------- MODULE WrongArity ----------------------------
(* Step is defined with one parameter but used with two.                   *)
(* Expected: semantic error at line 12.                                    *)
EXTENDS Naturals

VARIABLE x

Step(n) == x' = x + n

Init == x = 0

Next == x < 5 /\ Step(1, 2)
=============================================================================
