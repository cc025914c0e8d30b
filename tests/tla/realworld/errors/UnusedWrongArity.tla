--------------------------- MODULE UnusedWrongArity ---------------------------
(* Check applies Step, which takes one argument, to two; Check is used     *)
(* nowhere.  Expected: semantic error at line 9, column 14 (exit 150).    *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Step(n) == x' = x + n
Next == x < 3 /\ Step(1)
Check == Step(1, 2)
=============================================================================
