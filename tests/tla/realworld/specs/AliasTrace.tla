----------------------------- MODULE AliasTrace -----------------------------
(* ALIAS and POSTCONDITION in the .cfg: the counterexample shows the     *)
(* alias record (with TLCGet("level")), and the postcondition is not      *)
(* evaluated because the search stops at the violation.                  *)
(* TLC: Invariant Small is violated.                                      *)
EXTENDS Naturals, TLC
VARIABLES x, y
Init == x = 0 /\ y = 1
Next == \/ x' = x + 1 /\ y' = y * 2
        \/ x' = x /\ y' = y + 1 /\ y < 3
Small == x + y < 10
Alias == [step |-> TLCGet("level"), sum |-> x + y, x |-> x]
Post == TLCGet("stats").distinct > 0
=============================================================================
