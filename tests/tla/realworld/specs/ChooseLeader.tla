---------------------------- MODULE ChooseLeader ----------------------------
(* Deterministic choice with CHOOSE: the leader is the least live node;   *)
(* nodes crash and recover.  Constructs: CHOOSE x \in S : P (first        *)
(* witness in TLC's order), CHOOSE over tuples, Max/Min via CHOOSE.       *)
(* TLC: success.                                                          *)
EXTENDS Naturals
CONSTANT N
VARIABLES live, leader, history
Nodes == 1..N
Min(S) == CHOOSE m \in S : \A x \in S : m <= x
Init == live = Nodes /\ leader = Min(Nodes) /\ history = 0
Elect == leader' = IF live' = {} THEN 0 ELSE Min(live')
Crash(n) == /\ n \in live
            /\ live # {n}
            /\ live' = live \ {n}
            /\ Elect
            /\ history' = CHOOSE h \in 0..3 : h = (history + n) % 4
Recover(n) == /\ n \notin live
              /\ live' = live \cup {n}
              /\ Elect
              /\ history' = (CHOOSE <<a, b>> \in {<<h, 1>> : h \in 0..3} : a = (history + 1) % 4 /\ b = 1)[1]
Next == \E n \in Nodes : Crash(n) \/ Recover(n)
LeaderLive == leader \in live
=============================================================================
