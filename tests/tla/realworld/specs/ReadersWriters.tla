---------------------------- MODULE ReadersWriters ----------------------------
(* Readers and writers sharing a resource through a waiting queue, in the *)
(* style of the published ReadersWriters example.  Constructs: Seq of     *)
(* tuples, SelectSeq with a LAMBDA, Cardinality, records of sets.         *)
(* TLC: success.                                                          *)
EXTENDS FiniteSets, Naturals, Sequences
CONSTANT NumActors
VARIABLES readers, writers, waiting
vars == <<readers, writers, waiting>>
Actors == 1..NumActors
ToSet(s) == {s[i] : i \in DOMAIN s}
read(s) == s[1] = "read"
write(s) == s[1] = "write"
WaitingToRead == {p[2] : p \in ToSet(SelectSeq(waiting, read))}
WaitingToWrite == {p[2] : p \in ToSet(SelectSeq(waiting, write))}
Init == readers = {} /\ writers = {} /\ waiting = <<>>
TryRead(a) == /\ a \notin WaitingToRead
              /\ waiting' = Append(waiting, <<"read", a>>)
              /\ UNCHANGED <<readers, writers>>
TryWrite(a) == /\ a \notin WaitingToWrite
               /\ waiting' = Append(waiting, <<"write", a>>)
               /\ UNCHANGED <<readers, writers>>
Read(a) == /\ readers' = readers \cup {a}
           /\ waiting' = Tail(waiting)
           /\ UNCHANGED writers
Write(a) == /\ readers = {}
            /\ writers' = writers \cup {a}
            /\ waiting' = Tail(waiting)
            /\ UNCHANGED readers
ReadOrWrite == /\ waiting /= <<>>
               /\ writers = {}
               /\ LET pair == Head(waiting)
                      actor == pair[2]
                  IN CASE pair[1] = "read" -> Read(actor)
                       [] pair[1] = "write" -> Write(actor)
StopActivity(a) == \/ /\ a \in readers
                      /\ readers' = readers \ {a}
                      /\ UNCHANGED <<writers, waiting>>
                   \/ /\ a \in writers
                      /\ writers' = writers \ {a}
                      /\ UNCHANGED <<readers, waiting>>
Stop == \E a \in readers \cup writers : StopActivity(a)
Next == \/ \E a \in Actors : TryRead(a) \/ TryWrite(a)
        \/ ReadOrWrite
        \/ Stop
Spec == Init /\ [][Next]_vars
Safety == /\ ~(readers /= {} /\ writers /= {})
          /\ Cardinality(writers) <= 1
=============================================================================
