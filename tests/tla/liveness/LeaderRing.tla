---------------------------- MODULE LeaderRing ----------------------------
(* Chang-Roberts style leader election on a ring of N nodes: each node    *)
(* forwards the largest id it has seen to its successor.  With weak       *)
(* fairness on every node's send, every node eventually knows the maximum *)
(* and keeps it.  Expected: success.                                      *)
EXTENDS Naturals
VARIABLE best
N == 4
Nodes == 1..N
Id(n) == <<3, 1, 4, 2>>[n]
Succ(n) == IF n = N THEN 1 ELSE n + 1
Max == N
Init == best = [n \in Nodes |-> Id(n)]
Send(n) == /\ best[n] > best[Succ(n)]
           /\ best' = [best EXCEPT ![Succ(n)] = best[n]]
Next == \E n \in Nodes : Send(n)
Spec == Init /\ [][Next]_best /\ \A n \in Nodes : WF_best(Send(n))

Elected == <>(\A n \in Nodes : best[n] = Max)
Stable == <>[](\A n \in Nodes : best[n] = Max)
=============================================================================
