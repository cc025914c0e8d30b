------------------------------ MODULE TwoPhase ------------------------------
(***************************************************************************)
(* A two-phase commit protocol between one transaction manager (TM) and a  *)
(* set of resource managers (RMs).  Messages are never lost; they live in  *)
(* an ever-growing set `msgs`.  Each RM may prepare or spontaneously       *)
(* abort while it is working; the TM commits only once every RM has told   *)
(* it that it is prepared, and may abort at any time before deciding.      *)
(*                                                                         *)
(* Exercises: a CONSTANT set of model values, records and sets of records  *)
(* ([type : S, rm : T]), \cup, \subseteq, [S -> T], EXCEPT, \E over        *)
(* parameterised actions, \A with two bound variables, SPECIFICATION.      *)
(* Expected: success.  Terminal states still allow the "receive the        *)
(* decision again" steps, which loop back to the same state, so there is   *)
(* no deadlock.                                                            *)
(***************************************************************************)
CONSTANT RM

VARIABLES rmState, tmState, tmPrepared, msgs

vars == <<rmState, tmState, tmPrepared, msgs>>

Messages == [type : {"Prepared"}, rm : RM] \cup [type : {"Commit", "Abort"}]

TypeOK ==
    /\ rmState \in [RM -> {"working", "prepared", "committed", "aborted"}]
    /\ tmState \in {"init", "done"}
    /\ tmPrepared \subseteq RM
    /\ msgs \subseteq Messages

Init ==
    /\ rmState = [r \in RM |-> "working"]
    /\ tmState = "init"
    /\ tmPrepared = {}
    /\ msgs = {}

Send(m) == msgs' = msgs \cup {m}

TMRcvPrepared(r) ==
    /\ tmState = "init"
    /\ [type |-> "Prepared", rm |-> r] \in msgs
    /\ tmPrepared' = tmPrepared \cup {r}
    /\ UNCHANGED <<rmState, tmState, msgs>>

TMCommit ==
    /\ tmState = "init"
    /\ tmPrepared = RM
    /\ tmState' = "done"
    /\ Send([type |-> "Commit"])
    /\ UNCHANGED <<rmState, tmPrepared>>

TMAbort ==
    /\ tmState = "init"
    /\ tmState' = "done"
    /\ Send([type |-> "Abort"])
    /\ UNCHANGED <<rmState, tmPrepared>>

RMPrepare(r) ==
    /\ rmState[r] = "working"
    /\ rmState' = [rmState EXCEPT ![r] = "prepared"]
    /\ Send([type |-> "Prepared", rm |-> r])
    /\ UNCHANGED <<tmState, tmPrepared>>

RMChooseToAbort(r) ==
    /\ rmState[r] = "working"
    /\ rmState' = [rmState EXCEPT ![r] = "aborted"]
    /\ UNCHANGED <<tmState, tmPrepared, msgs>>

RMRcvCommit(r) ==
    /\ [type |-> "Commit"] \in msgs
    /\ rmState' = [rmState EXCEPT ![r] = "committed"]
    /\ UNCHANGED <<tmState, tmPrepared, msgs>>

RMRcvAbort(r) ==
    /\ [type |-> "Abort"] \in msgs
    /\ rmState' = [rmState EXCEPT ![r] = "aborted"]
    /\ UNCHANGED <<tmState, tmPrepared, msgs>>

Next ==
    \/ TMCommit
    \/ TMAbort
    \/ \E r \in RM :
          \/ TMRcvPrepared(r)
          \/ RMPrepare(r)
          \/ RMChooseToAbort(r)
          \/ RMRcvCommit(r)
          \/ RMRcvAbort(r)

Spec == Init /\ [][Next]_vars

\* No resource manager commits while another aborts.
Consistent ==
    \A r1, r2 \in RM : ~ /\ rmState[r1] = "aborted"
                         /\ rmState[r2] = "committed"
=============================================================================
