----------------------------- MODULE TokenRing -----------------------------
(* A token passed around a ring of N nodes, with a per-node INSTANCE      *)
(* (Node(i) == INSTANCE TokenRingNode WITH ...) and a counter of passes.  *)
(* Constructs: parameterised INSTANCE, N!Op, implicit substitution of     *)
(* holder, % arithmetic.  TLC: success.                                   *)
EXTENDS Naturals
CONSTANT N
VARIABLES holder, passes
Node(i) == INSTANCE TokenRingNode WITH Self <- i, Succ <- (i + 1) % N
Init == holder = 0 /\ passes = 0
Next == \E i \in 0..(N - 1) : Node(i)!Pass /\ passes' = (passes + 1) % (2 * N)
Cardinality(S) == LET f[T \in SUBSET S] == IF T = {} THEN 0 ELSE 1 + f[T \ {CHOOSE x \in T : TRUE}]
                  IN f[S]
OneHolder == Cardinality({i \in 0..(N - 1) : Node(i)!HasToken}) = 1
=============================================================================
