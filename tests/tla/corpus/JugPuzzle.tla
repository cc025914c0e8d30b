----------------------------- MODULE JugPuzzle -----------------------------
(***************************************************************************)
(* The water-jug puzzle: with a small jug, a big jug, a tap and a drain,   *)
(* measure out exactly Goal gallons.  NotSolved claims that the big jug    *)
(* never holds Goal gallons; TLC refutes it, and since the search is       *)
(* breadth-first the counterexample is a shortest solution.                *)
(*                                                                         *)
(* Exercises: integer CONSTANTS, operators with parameters, LET, IF, a     *)
(* disjunction bullet list, UNCHANGED, INVARIANTS with two names.          *)
(* Expected: safety failure of NotSolved.                                  *)
(***************************************************************************)
EXTENDS Naturals

CONSTANTS SmallCap, BigCap, Goal

VARIABLES small, big

Min(a, b) == IF a < b THEN a ELSE b

TypeOK == /\ small \in 0..SmallCap
          /\ big \in 0..BigCap

Init == small = 0 /\ big = 0

FillSmall  == small' = SmallCap /\ UNCHANGED big
FillBig    == big' = BigCap /\ UNCHANGED small
EmptySmall == small' = 0 /\ UNCHANGED big
EmptyBig   == big' = 0 /\ UNCHANGED small

\* Pour from one jug into the other until the source is empty or the
\* destination is full, whichever comes first.
SmallToBig == LET amount == Min(small, BigCap - big)
              IN  /\ small' = small - amount
                  /\ big' = big + amount

BigToSmall == LET amount == Min(big, SmallCap - small)
              IN  /\ big' = big - amount
                  /\ small' = small + amount

Next == \/ FillSmall
        \/ FillBig
        \/ EmptySmall
        \/ EmptyBig
        \/ SmallToBig
        \/ BigToSmall

NotSolved == big /= Goal
=============================================================================
