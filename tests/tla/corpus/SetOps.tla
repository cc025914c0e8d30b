------------------------------ MODULE SetOps ------------------------------
(***************************************************************************)
(* Two sets evolve: `chosen` gains or loses one element of U at a time,    *)
(* and `marked` is always some subset of `chosen`, picked                  *)
(* nondeterministically from SUBSET chosen.  The invariants are set        *)
(* identities; the state space is every pair marked \subseteq chosen       *)
(* \subseteq U, i.e. 3^|U| states.                                         *)
(*                                                                         *)
(* Exercises: set enumeration, {x \in S : P}, {e : x \in S}, SUBSET,       *)
(* UNION, \cup, \cap, \, \subseteq, \in, \notin, .., \X, Cardinality,      *)
(* x' \in SUBSET S, the empty set and empty ranges.  Expected: success.    *)
(***************************************************************************)
EXTENDS Naturals, FiniteSets

CONSTANT U

VARIABLES chosen, marked

Init == chosen = {} /\ marked = {}

Add    == \E e \in U \ chosen : /\ chosen' = chosen \cup {e}
                                /\ marked' \in SUBSET chosen'
Remove == \E e \in chosen :     /\ chosen' = chosen \ {e}
                                /\ marked' = marked \cap chosen'

Next == Add \/ Remove

TypeOK == chosen \in SUBSET U /\ marked \subseteq chosen

Identities ==
    /\ {x \in chosen : x \notin marked} = chosen \ marked
    /\ UNION {{x} : x \in chosen} = chosen
    /\ UNION {marked, chosen \ marked} = chosen
    /\ {x + 0 : x \in marked} \cup {} = marked
    /\ chosen \cap marked = marked
    /\ Cardinality(chosen \X marked) = Cardinality(chosen) * Cardinality(marked)
    /\ Cardinality(SUBSET marked) = 2 ^ Cardinality(marked)
    /\ Cardinality({<<x, y>> \in chosen \X chosen : x < y})
         = (Cardinality(chosen) * (Cardinality(chosen) - 1)) \div 2
    /\ 3..2 = {}
    /\ {1, 1, 2} = 1..2
    /\ \A x \in marked : x \in chosen
    /\ (chosen = U) \/ \E x \in U : x \notin chosen
=============================================================================
