----------------------------- MODULE Constructs -----------------------------
(* Every construct the prover translates, in one small spec: a bounded   *)
(* queue of records (Seq + Len bound), a function over 1..3, a record    *)
(* with EXCEPT and @, strings, CASE, LET, IF, \E over finite sets,       *)
(* UNCHANGED, a symbolic integer constant and a symbolic subset.          *)
EXTENDS Naturals, Sequences
CONSTANTS Cap, Ids
ASSUME Cap \in 1..4
ASSUME Ids \subseteq {"a", "b", "c"}
VARIABLES queue, f, rec, phase, count

Names == {"a", "b", "c"}
Msg == [id : Names, n : 0..3]

Init == /\ queue = << >>
        /\ f = [i \in 1..3 |-> "a"]
        /\ rec = [mode |-> "off", level |-> 0]
        /\ phase = "idle"
        /\ count = 0

Send == \E id \in Ids, n \in 0..3 :
          /\ Len(queue) < Cap
          /\ queue' = Append(queue, [id |-> id, n |-> n])
          /\ UNCHANGED <<f, rec, phase, count>>

Recv == /\ queue # << >>
        /\ LET m == Head(queue) IN
             /\ queue' = Tail(queue)
             /\ f' = [f EXCEPT ![1 + (m.n % 3)] = m.id]
             /\ rec' = [rec EXCEPT !.level = IF @ < 5 THEN @ + 1 ELSE @]
             /\ phase' = CASE m.n = 0 -> "idle" [] m.n = 1 -> "busy" [] OTHER -> "done"
             /\ count' = IF count < Cap THEN count + 1 ELSE 0

Toggle == /\ rec' = [rec EXCEPT !.mode = IF @ = "off" THEN "on" ELSE "off"]
          /\ UNCHANGED <<queue, f, phase, count>>

Next == Send \/ Recv \/ Toggle

TypeOK == /\ queue \in Seq(Msg) /\ Len(queue) <= Cap
          /\ f \in [1..3 -> Names]
          /\ rec \in [mode : {"on", "off"}, level : 0..5]
          /\ phase \in {"idle", "busy", "done"}
          /\ count \in 0..Cap

\* Needs FromIds as strengthening: f takes its values from the queue.
FValues == \A i \in 1..3 : f[i] = "a" \/ f[i] \in Ids
FromIds == \A i \in DOMAIN queue : queue[i].id \in Ids
\* Violated: five receptions, each after a send (10 steps, 11 states).
LevelBelow5 == rec.level < 5
=============================================================================
