---------------------------- MODULE SyntaxError ----------------------------
(* A syntax error: the conjunction in Next is missing its right operand.   *)
(* Expected: TLC's parser rejects the module (line 13).                    *)
EXTENDS Naturals

VARIABLE x

Init == x = 0

Next == /\ x < 3
        /\ x' = x + 1
        /\
Inv == x < 10
=============================================================================
