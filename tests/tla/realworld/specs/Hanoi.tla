------------------------------- MODULE Hanoi -------------------------------
(* Towers of Hanoi with towers as sequences (top of stack first): TLC     *)
(* finds the solution as a violation of NotSolved.  Constructs: Seq ops,  *)
(* <<>> tests, \E over pairs, recursive sum check.  TLC: Invariant        *)
(* NotSolved is violated.                                                 *)
EXTENDS Naturals, Sequences
CONSTANTS D
Towers == 1..3
VARIABLE towers
Init == towers = [t \in Towers |-> IF t = 1 THEN [i \in 1..D |-> i] ELSE <<>>]
CanMove(from, to) == /\ towers[from] # <<>>
                     /\ IF towers[to] = <<>> THEN TRUE ELSE Head(towers[from]) < Head(towers[to])
Move(from, to) == /\ from # to
                  /\ CanMove(from, to)
                  /\ towers' = [towers EXCEPT ![from] = Tail(@), ![to] = <<Head(towers[from])>> \o @]
Next == \E from, to \in Towers : Move(from, to)
RECURSIVE Sum(_)
Sum(s) == IF s = <<>> THEN 0 ELSE Head(s) + Sum(Tail(s))
Conserved == Sum(towers[1]) + Sum(towers[2]) + Sum(towers[3]) = (D * (D + 1)) \div 2
NotSolved == Len(towers[3]) < D
=============================================================================
