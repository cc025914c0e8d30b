---------------------------- MODULE TLCFeatures ----------------------------
(***************************************************************************)
(* A ranking game among interchangeable players (model values): any        *)
(* player below the top rank may be promoted; when everyone is at the top  *)
(* rank, all are reset.  The players are symmetric, so the cfg checks it   *)
(* under SYMMETRY.                                                         *)
(*                                                                         *)
(* Exercises the TLC module: Print and PrintT (in ASSUMEs, so each prints  *)
(* exactly once, before the search), Assert in an action (never fails),    *)
(* :> and @@, Permutations with SYMMETRY, SortSeq, ToString; and a         *)
(* RECURSIVE operator turning a set into a sequence with CHOOSE.           *)
(* Expected: success; before "Computing initial states" TLC prints the two *)
(* lines  "TLCFeatures starting"  and  <<"players", 4>>  TRUE  (Print      *)
(* shows its first argument, two spaces, then its second).                 *)
(***************************************************************************)
EXTENDS Naturals, Sequences, FiniteSets, TLC

CONSTANTS Players, Top

ASSUME PrintT("TLCFeatures starting")
ASSUME Print(<<"players", Cardinality(Players)>>, Top \in Nat)

VARIABLE rank

Init == rank = [p \in Players |-> 1]

Promote(p) ==
    /\ rank[p] < Top
    /\ Assert(rank[p] \in 1..(Top - 1), "promoting a player at the top")
    /\ rank' = [rank EXCEPT ![p] = @ + 1]

Reset ==
    /\ \A p \in Players : rank[p] = Top
    /\ rank' = [p \in Players |-> 1]

Next == Reset \/ \E p \in Players : Promote(p)

Perms == Permutations(Players)

RECURSIVE SetToSeq(_)
SetToSeq(S) == IF S = {} THEN << >>
               ELSE LET x == CHOOSE x \in S : TRUE
                    IN  << x >> \o SetToSeq(S \ {x})

\* The multiset of ranks, as a sorted sequence.  It does not depend on which
\* player holds which rank, so it is symmetric.
Ranks == LET s == SetToSeq(Players)
         IN  SortSeq([i \in 1..Len(s) |-> rank[s[i]]], LAMBDA u, v : u < v)

Sorted == \A i \in 1..(Len(Ranks) - 1) : Ranks[i] <= Ranks[i + 1]

Misc ==
    /\ ToString(Len(Ranks)) = "4"
    /\ ToString(<<1, "a">>) = "<<1, \"a\">>"
    /\ LET f == (1 :> Ranks[1]) @@ (2 :> Ranks[2]) @@ (1 :> 99)
       IN  f[1] = Ranks[1] /\ DOMAIN f = {1, 2}
    /\ Cardinality(Perms) = 24
=============================================================================
