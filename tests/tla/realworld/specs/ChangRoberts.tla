---------------------------- MODULE ChangRoberts ----------------------------
(* Chang and Roberts' leader election on a unidirectional ring, in the    *)
(* style of the published example: node identities are a permutation,   *)
(* messages are bags of identities (functions to counts) per node.        *)
(* Constructs: IF chains, functions of sets, CHOOSE-defined identities,   *)
(* \A/\E.  TLC: success.                                                  *)
EXTENDS Naturals, Sequences
CONSTANT N
Id == [n \in 1..N |-> IF n = 1 THEN N ELSE n - 1]
Node == 1..N
succ(n) == IF n = N THEN 1 ELSE n + 1
VARIABLES msgs, pc, initiator
vars == <<msgs, pc, initiator>>
Init == /\ msgs = [n \in Node |-> {}]
        /\ pc = [n \in Node |-> "start"]
        /\ initiator \in [Node -> BOOLEAN]
Send(n) == /\ pc[n] = "start"
           /\ initiator[n]
           /\ msgs' = [msgs EXCEPT ![succ(n)] = @ \cup {Id[n]}]
           /\ pc' = [pc EXCEPT ![n] = "wait"]
           /\ UNCHANGED initiator
Lose(n) == /\ pc[n] = "start"
           /\ ~initiator[n]
           /\ pc' = [pc EXCEPT ![n] = "lost"]
           /\ UNCHANGED <<msgs, initiator>>
Receive(n) == \E id \in msgs[n] :
                /\ msgs' = IF id = Id[n] THEN [msgs EXCEPT ![n] = @ \ {id}]
                           ELSE IF id > Id[n]
                                THEN [msgs EXCEPT ![n] = @ \ {id}, ![succ(n)] = @ \cup {id}]
                                ELSE [msgs EXCEPT ![n] = @ \ {id}]
                /\ pc' = IF id = Id[n] THEN [pc EXCEPT ![n] = "won"]
                         ELSE IF id > Id[n] THEN [pc EXCEPT ![n] = "lost"] ELSE pc
                /\ UNCHANGED initiator
Next == \E n \in Node : Send(n) \/ Lose(n) \/ Receive(n)
Spec == Init /\ [][Next]_vars
Safety == \A m, n \in Node : pc[m] = "won" /\ pc[n] = "won" => m = n
=============================================================================
