------------------------------ MODULE QueueMutex ------------------------------
(***************************************************************************)
(* A benchmark with sequences and records: N processes share a lock held  *)
(* by a server.  A process sends a request record to the server's FIFO    *)
(* inbox; the server queues requests and grants the lock to the head of   *)
(* its queue by a message into that process's channel; the holder enters *)
(* the critical section, then releases.  Tickets and per-process entry    *)
(* counters wrap, which keeps the state space finite.                     *)
(***************************************************************************)
EXTENDS Naturals, Sequences

CONSTANTS N, MaxTicket, MaxEntries

Procs == 1..N
Msg == [kind : {"grant"}, ticket : 0..MaxTicket - 1]

VARIABLES pc, inbox, waiting, chan, holder, ticket, entries

vars == <<pc, inbox, waiting, chan, holder, ticket, entries>>

TypeOK ==
    /\ pc \in [Procs -> {"idle", "requested", "cs"}]
    /\ \A i \in 1..Len(inbox) : inbox[i].proc \in Procs
    /\ \A i \in 1..Len(waiting) : waiting[i].proc \in Procs /\ waiting[i].ticket \in 0..MaxTicket - 1
    /\ chan \in [Procs -> Seq(Msg)]
    /\ holder \in Procs \cup {0}
    /\ entries \in [Procs -> 0..MaxEntries - 1]

Init ==
    /\ pc = [p \in Procs |-> "idle"]
    /\ inbox = <<>>
    /\ waiting = <<>>
    /\ chan = [p \in Procs |-> <<>>]
    /\ holder = 0
    /\ ticket = 0
    /\ entries = [p \in Procs |-> 0]

Request(p) ==
    /\ pc[p] = "idle"
    /\ pc' = [pc EXCEPT ![p] = "requested"]
    /\ inbox' = Append(inbox, [proc |-> p, op |-> "acquire"])
    /\ UNCHANGED <<waiting, chan, holder, ticket, entries>>

Receive ==
    /\ inbox /= <<>>
    /\ LET m == Head(inbox) IN
         IF m.op = "acquire"
         THEN /\ waiting' = Append(waiting, [proc |-> m.proc, ticket |-> ticket])
              /\ ticket' = (ticket + 1) % MaxTicket
              /\ UNCHANGED holder
         ELSE /\ holder' = 0
              /\ UNCHANGED <<waiting, ticket>>
    /\ inbox' = Tail(inbox)
    /\ UNCHANGED <<pc, chan, entries>>

Grant ==
    /\ holder = 0
    /\ waiting /= <<>>
    /\ LET w == Head(waiting) IN
         /\ holder' = w.proc
         /\ chan' = [chan EXCEPT ![w.proc] = Append(@, [kind |-> "grant", ticket |-> w.ticket])]
    /\ waiting' = Tail(waiting)
    /\ UNCHANGED <<pc, inbox, ticket, entries>>

Enter(p) ==
    /\ pc[p] = "requested"
    /\ chan[p] /= <<>>
    /\ Head(chan[p]).kind = "grant"
    /\ pc' = [pc EXCEPT ![p] = "cs"]
    /\ chan' = [chan EXCEPT ![p] = Tail(@)]
    /\ entries' = [entries EXCEPT ![p] = (@ + 1) % MaxEntries]
    /\ UNCHANGED <<inbox, waiting, holder, ticket>>

Release(p) ==
    /\ pc[p] = "cs"
    /\ pc' = [pc EXCEPT ![p] = "idle"]
    /\ inbox' = Append(inbox, [proc |-> p, op |-> "release"])
    /\ UNCHANGED <<waiting, chan, holder, ticket, entries>>

Next ==
    \/ \E p \in Procs : Request(p) \/ Enter(p) \/ Release(p)
    \/ Receive
    \/ Grant

Spec == Init /\ [][Next]_vars

MutualExclusion == \A p, q \in Procs : p /= q => ~(pc[p] = "cs" /\ pc[q] = "cs")
=============================================================================
