--------------------------- MODULE RecursiveAction ---------------------------
(* A RECURSIVE operator that primes variables (an action-level recursion):  *)
(* Serve(S) serves one request of S, trying them in CHOOSE order, each try  *)
(* a disjunct.  TLC descends into it at every call with the argument's     *)
(* value.  TLC 1.8.0: invariant Bounded violated, 21 distinct states,      *)
(* 49 generated, depth 6, a 6-state trace.                                *)
EXTENDS Naturals, FiniteSets
VARIABLES served, count

RECURSIVE Serve(_)
Serve(S) == IF S = {} THEN UNCHANGED served /\ count' = count
            ELSE LET r == CHOOSE r \in S : TRUE
                 IN \/ r \notin served /\ served' = served \cup {r} /\ count' = count + 1
                    \/ Serve(S \ {r})

Init == served = {} /\ count = 0
Next == \/ count < 4 /\ Serve({1, 2, 3})
        \/ served # {} /\ served' = {} /\ UNCHANGED count
Bounded == count < 4
=============================================================================
