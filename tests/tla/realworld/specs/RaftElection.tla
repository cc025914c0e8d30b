--------------------------- MODULE RaftElection ---------------------------
(* A bounded Raft-like leader election: servers time out, become          *)
(* candidates in a new term, request votes, and win with a majority.      *)
(* Constructs: records in a message set, CASE, Cardinality, term bound    *)
(* via a state constraint.  TLC: success (ElectionSafety holds).          *)
EXTENDS Naturals, FiniteSets
CONSTANTS Server, MaxTerm
VARIABLES currentTerm, state, votedFor, votesGranted, msgs
vars == <<currentTerm, state, votedFor, votesGranted, msgs>>
Nil == "none"
Majority(S) == 2 * Cardinality(S) > Cardinality(Server)
Init == /\ currentTerm = [s \in Server |-> 0]
        /\ state = [s \in Server |-> "Follower"]
        /\ votedFor = [s \in Server |-> Nil]
        /\ votesGranted = [s \in Server |-> {}]
        /\ msgs = {}
Timeout(s) == /\ state[s] \in {"Follower", "Candidate"}
              /\ currentTerm[s] < MaxTerm
              /\ currentTerm' = [currentTerm EXCEPT ![s] = @ + 1]
              /\ state' = [state EXCEPT ![s] = "Candidate"]
              /\ votedFor' = [votedFor EXCEPT ![s] = s]
              /\ votesGranted' = [votesGranted EXCEPT ![s] = {s}]
              /\ msgs' = msgs \cup {[type |-> "RequestVote", term |-> currentTerm[s] + 1, src |-> s]}
HandleRequestVote(s, m) ==
    /\ m.type = "RequestVote"
    /\ m.src # s
    /\ LET grant == /\ m.term >= currentTerm[s]
                    /\ \/ m.term > currentTerm[s]
                       \/ votedFor[s] \in {Nil, m.src}
       IN /\ grant
          /\ currentTerm' = [currentTerm EXCEPT ![s] = m.term]
          /\ state' = [state EXCEPT ![s] = IF m.term > currentTerm[s] THEN "Follower" ELSE @]
          /\ votedFor' = [votedFor EXCEPT ![s] = m.src]
          /\ msgs' = msgs \cup {[type |-> "Vote", term |-> m.term, src |-> s, dst |-> m.src]}
          /\ UNCHANGED votesGranted
HandleVote(s, m) ==
    /\ m.type = "Vote"
    /\ m.dst = s
    /\ m.term = currentTerm[s]
    /\ state[s] = "Candidate"
    /\ m.src \notin votesGranted[s]
    /\ votesGranted' = [votesGranted EXCEPT ![s] = @ \cup {m.src}]
    /\ UNCHANGED <<currentTerm, state, votedFor, msgs>>
BecomeLeader(s) == /\ state[s] = "Candidate"
                   /\ Majority(votesGranted[s])
                   /\ state' = [state EXCEPT ![s] = "Leader"]
                   /\ UNCHANGED <<currentTerm, votedFor, votesGranted, msgs>>
Next == \/ \E s \in Server : Timeout(s) \/ BecomeLeader(s)
        \/ \E s \in Server, m \in msgs : HandleRequestVote(s, m) \/ HandleVote(s, m)
Spec == Init /\ [][Next]_vars
ElectionSafety == \A s, t \in Server :
                     (s # t /\ state[s] = "Leader" /\ state[t] = "Leader") => currentTerm[s] # currentTerm[t]
StateName(s) == CASE state[s] = "Leader" -> 2 [] state[s] = "Candidate" -> 1 [] OTHER -> 0
TypeOK == \A s \in Server : StateName(s) \in 0..2 /\ currentTerm[s] \in 0..MaxTerm
=============================================================================
