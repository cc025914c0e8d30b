------------------------- MODULE FalsePostcondition -------------------------
(* The POSTCONDITION claims 4 distinct states; there are 3.               *)
(* Expected: "Postcondition Post ... is false", exit 10.                  *)
EXTENDS Naturals, TLC
VARIABLE x
Init == x = 0
Next == x < 2 /\ x' = x + 1
Post == TLCGet("stats").distinct = 4
=============================================================================
