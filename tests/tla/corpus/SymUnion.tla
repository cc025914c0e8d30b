------------------------------- MODULE SymUnion -------------------------------
(***************************************************************************)
(* SYMMETRY given as a union of two Permutations sets, the common idiom    *)
(* (Permutations(A) \cup Permutations(B)).  That set is not a group; TLC   *)
(* closes it under composition (the whole product group, 3! * 2! = 12      *)
(* permutations) and keeps the smallest image of each state.  Reducing by  *)
(* the 7 listed permutations only gives 140 distinct states, not TLC's 65. *)
(***************************************************************************)
EXTENDS TLC
CONSTANTS A, B, none
VARIABLES assign, log

Init == assign = [a \in A |-> none] /\ log = {}

Take(a, b) == /\ assign[a] = none
              /\ assign' = [assign EXCEPT ![a] = b]
              /\ log' = log \cup {<<a, b>>}

Drop(a) == /\ assign[a] # none
           /\ assign' = [assign EXCEPT ![a] = none]
           /\ UNCHANGED log

Next == (\E a \in A, b \in B : Take(a, b)) \/ (\E a \in A : Drop(a))

Sym == Permutations(A) \cup Permutations(B)

TypeOK == assign \in [A -> B \cup {none}] /\ log \subseteq A \X B
=============================================================================
