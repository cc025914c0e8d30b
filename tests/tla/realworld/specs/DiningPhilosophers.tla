------------------------ MODULE DiningPhilosophers ------------------------
(* Dining philosophers with forks as a function from fork to holder; the  *)
(* naive protocol (left fork first) deadlocks.  Constructs: modular       *)
(* arithmetic, functions, CASE.  TLC: Deadlock reached.                   *)
EXTENDS Naturals
CONSTANT N
P == 0..(N - 1)
NoOne == N
VARIABLES fork, phase
vars == <<fork, phase>>
Left(p) == p
Right(p) == (p + 1) % N
Init == fork = [f \in P |-> NoOne] /\ phase = [p \in P |-> "think"]
TakeLeft(p) == /\ phase[p] = "think"
               /\ fork[Left(p)] = NoOne
               /\ fork' = [fork EXCEPT ![Left(p)] = p]
               /\ phase' = [phase EXCEPT ![p] = "hungry"]
TakeRight(p) == /\ phase[p] = "hungry"
                /\ fork[Right(p)] = NoOne
                /\ fork' = [fork EXCEPT ![Right(p)] = p]
                /\ phase' = [phase EXCEPT ![p] = "eat"]
Release(p) == /\ phase[p] = "eat"
              /\ fork' = [f \in P |-> IF fork[f] = p THEN NoOne ELSE fork[f]]
              /\ phase' = [phase EXCEPT ![p] = "think"]
Next == \E p \in P : TakeLeft(p) \/ TakeRight(p) \/ Release(p)
Spec == Init /\ [][Next]_vars
Eating(p) == CASE phase[p] = "eat" -> TRUE [] OTHER -> FALSE
NoNeighboursEat == \A p \in P : ~(Eating(p) /\ Eating(Right(p)))
=============================================================================
