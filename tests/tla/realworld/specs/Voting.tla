------------------------------ MODULE Voting ------------------------------
(* A fragment of Paxos consensus in the style of Lamport's Voting spec:   *)
(* acceptors vote for values in ballots; quorums are majorities.          *)
(* Constructs: SUBSET with a filter for quorums, sets of tuples, \E over  *)
(* several binders, CHOOSE-free safety invariant.  TLC: success.          *)
EXTENDS Integers, FiniteSets
CONSTANTS Value, Acceptor, MaxBallot
Ballot == 0..MaxBallot
Quorum == {Q \in SUBSET Acceptor : 2 * Cardinality(Q) > Cardinality(Acceptor)}
VARIABLES votes, maxBal
vars == <<votes, maxBal>>
TypeOK == /\ votes \in [Acceptor -> SUBSET (Ballot \X Value)]
          /\ maxBal \in [Acceptor -> Ballot \cup {-1}]
VotedFor(a, b, v) == <<b, v>> \in votes[a]
ChosenAt(b, v) == \E Q \in Quorum : \A a \in Q : VotedFor(a, b, v)
chosen == {v \in Value : \E b \in Ballot : ChosenAt(b, v)}
DidNotVoteAt(a, b) == \A v \in Value : ~VotedFor(a, b, v)
CannotVoteAt(a, b) == maxBal[a] > b /\ DidNotVoteAt(a, b)
NoneOtherChoosableAt(b, v) ==
    \E Q \in Quorum : \A a \in Q : VotedFor(a, b, v) \/ CannotVoteAt(a, b)
SafeAt(b, v) == \A c \in 0..(b - 1) : NoneOtherChoosableAt(c, v)
Init == votes = [a \in Acceptor |-> {}] /\ maxBal = [a \in Acceptor |-> -1]
IncreaseMaxBal(a, b) == /\ b > maxBal[a]
                        /\ maxBal' = [maxBal EXCEPT ![a] = b]
                        /\ UNCHANGED votes
VoteFor(a, b, v) == /\ maxBal[a] <= b
                    /\ \A vt \in votes[a] : vt[1] # b
                    /\ \A c \in Acceptor \ {a} : \A vt \in votes[c] : vt[1] = b => vt[2] = v
                    /\ SafeAt(b, v)
                    /\ votes' = [votes EXCEPT ![a] = @ \cup {<<b, v>>}]
                    /\ maxBal' = [maxBal EXCEPT ![a] = b]
Next == \E a \in Acceptor, b \in Ballot :
          \/ IncreaseMaxBal(a, b)
          \/ \E v \in Value : VoteFor(a, b, v)
Spec == Init /\ [][Next]_vars
Consistency == \A v, w \in chosen : v = w
=============================================================================
