---------------------------- MODULE Constraints ----------------------------
(***************************************************************************)
(* Two unbounded counters: x counts up, y counts up, and a transfer moves  *)
(* one unit from x to two units of y.  The state space is infinite; the    *)
(* cfg bounds it with two state constraints, and two action constraints    *)
(* forbid transfers once y is large and any growth of y except by a        *)
(* transfer, so only y \in {0, 2, 4, 6} is reached.                        *)
(*                                                                         *)
(* Exercises: CONSTRAINTS with two names, ACTION_CONSTRAINTS with two      *)
(* names (an action constraint may mention primed variables), primed       *)
(* expressions in a constraint, UNCHANGED.                                 *)
(* TLC counts a successor that violates a constraint in "states            *)
(* generated" but not in "distinct states"; it is never explored, yet the  *)
(* invariants are still checked on it.  Expected: success.                 *)
(***************************************************************************)
EXTENDS Naturals

VARIABLES x, y

Init == x = 0 /\ y = 0

IncX     == x' = x + 1 /\ UNCHANGED y
IncY     == y' = y + 1 /\ UNCHANGED x
Transfer == x > 0 /\ x' = x - 1 /\ y' = y + 2

Next == IncX \/ IncY \/ Transfer

\* State constraints.
XBound == x <= 6
YBound == y <= 8

\* Action constraints.
NoTransferWhenRich == (x' < x) => y < 5
YOnlyByTransfer    == y' > y => x' < x

TypeOK == x \in Nat /\ y \in Nat
Within == x <= 7 /\ y <= 10
=============================================================================
