---------------------------- MODULE NestedExcept ----------------------------
(* A replicated register table: per-node records holding a function of    *)
(* versions, updated with nested EXCEPT paths and @ (![n].ver[k] = @ + 1, *)
(* ![n].log = Append(@, ..), several updates in one EXCEPT).              *)
(* TLC: Invariant VersionsBounded is violated.                            *)
EXTENDS Naturals, Sequences
CONSTANTS Node, Key
VARIABLE table
Init == table = [n \in Node |-> [ver |-> [k \in Key |-> 0], log |-> <<>>, up |-> TRUE]]
Bump(n, k) == /\ table[n].up
              /\ table' = [table EXCEPT ![n].ver[k] = @ + 1,
                                        ![n].log = Append(@, k),
                                        ![n].up = Len(table[n].log) < 1]
Restart(n) == /\ ~table[n].up
              /\ table' = [table EXCEPT ![n] = [@ EXCEPT !.up = TRUE, !.log = <<>>]]
Next == \E n \in Node : Restart(n) \/ \E k \in Key : Bump(n, k)
VersionsBounded == \A n \in Node : \A k \in Key : table[n].ver[k] <= 2
=============================================================================
