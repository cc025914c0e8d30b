----------------------------- MODULE TLCStats -----------------------------
(* TLCGet and TLCSet: a search bounded by TLCGet("level") in a state      *)
(* constraint, a register counting steps, and a POSTCONDITION reading the *)
(* final statistics ("distinct", "queue", "diameter", "stats").           *)
(* TLC: success.                                                          *)
EXTENDS Naturals, TLC
VARIABLES x, y
ASSUME TLCSet(1, 0)
Init == x = 0 /\ y = 0
Next == /\ TLCSet(1, TLCGet(1) + 1)
        /\ \/ x' = x + 1 /\ y' = y
           \/ y' = (y + 1) % 3 /\ x' = x
Depth == TLCGet("level") < 6
Sane == /\ TLCGet("level") >= 1
        /\ TLCGet("distinct") >= 1
        /\ TLCGet("queue") >= 0
        /\ TLCGet("diameter") >= TLCGet("level") - 1
        /\ x <= 5
Post == /\ TLCGet("stats").distinct = 12
        /\ TLCGet("stats").diameter = 5
        /\ TLCGet("stats").queue = 0
        /\ TLCGet(1) > 0
=============================================================================
