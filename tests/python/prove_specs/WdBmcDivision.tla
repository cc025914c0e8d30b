--------------------------- MODULE WdBmcDivision ---------------------------
(* 3 \div y on the first step, with y = 0 in the initial state: TLC stops  *)
(* with an evaluation error there; the invariant holds whatever x is.      *)
EXTENDS Integers
VARIABLE x, y

Init == x = 0 /\ y = 0
Next == x' = 3 \div y /\ y' = y

TypeOK == x \in Int /\ y \in Int
Anything == x \in Int
=============================================================================
