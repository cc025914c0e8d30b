------------------------------ MODULE StateChain ------------------------------
(* The state-chain engine of docs/design/state-chain.md (SCH-01 .. SCH-04)   *)
(* for any tree given as constants. One step = one engine call: a transition *)
(* request (accepted or rejected) or one scan's run walk. `log` records the  *)
(* entry/exit/run calls of the last step in call order.                     *)
EXTENDS Naturals, Sequences, FiniteSets

CONSTANTS
    Order,          \* every state once, in table order: pre-order (parent first, subtrees contiguous)
    Parent,         \* [state -> parent state or NoState]
    InitialChild,   \* [state -> initial child or NoState]
    ParallelStates, \* states whose children are sub-chain roots
    NoState

States == {Order[i] : i \in 1..Len(Order)}
Root == CHOOSE s \in States : Parent[s] = NoState

VARIABLES active, log, result, request
chainVars == <<active, log, result, request>>

Children(s) == {c \in States : Parent[c] = s}
Index(s) == CHOOSE i \in 1..Len(Order) : Order[i] = s
InOrder(set) == SelectSeq(Order, LAMBDA c : c \in set)
Reverse(sq) == [i \in 1..Len(sq) |-> sq[Len(sq) - i + 1]]

\* Ancestors without RECURSIVE (safestate check refuses recursive operators
\* over these values, see the report): trees of depth <= 7 (ASSUMEd below).
Up(s) == IF s = NoState THEN NoState ELSE Parent[s]
Ancestors(s) ==
    LET p1 == Up(s)  p2 == Up(p1)  p3 == Up(p2)  p4 == Up(p3)
        p5 == Up(p4) p6 == Up(p5)  p7 == Up(p6)
    IN {p1, p2, p3, p4, p5, p6, p7} \ {NoState}
ASSUME \A s \in States : Up(Up(Up(Up(Up(Up(Up(Up(s)))))))) = NoState
IsAncestor(a, s) == a \in Ancestors(s)
SubTree(s) == {d \in States : d = s \/ IsAncestor(s, d)}

\* The table lists the states in pre-order (a parent before its children, a
\* subtree contiguous), so pre-order is table order: §2 entry is ascending
\* table order, §3 exit and §5 run (post-order, children in reverse) are
\* descending table order. Sequences are built without recursion.
ASSUME \A s \in States : Parent[s] # NoState => Index(Parent[s]) < Index(s)
ASSUME \A i \in 1..Len(Order) : \A j \in i..Len(Order) :
           Order[j] \in SubTree(Order[i]) => \A k \in i..j : Order[k] \in SubTree(Order[i])

Event(k, s) == [kind |-> k, state |-> s]
Events(k, sq) == [i \in DOMAIN sq |-> Event(k, sq[i])]

\* §2 the states enter(s) activates: s, and below it every state whose path
\* from s goes only through parallel children and initial children.
DefaultChild(c) == Parent[c] \in ParallelStates \/ InitialChild[Parent[c]] = c
EnterSet(s) == {d \in SubTree(s) : \A a \in SubTree(s) : (a # s /\ (a = d \/ IsAncestor(a, d))) => DefaultChild(a)}
EnterSeq(s) == Events("entry", InOrder(EnterSet(s)))
\* §3 exit(s): the active states of the subtree, leaf first; §5 run the same walk.
LeaveSeq(k, s, act) == Events(k, Reverse(InOrder(SubTree(s) \cap act)))

StatesOf(sq) == {sq[i].state : i \in DOMAIN sq}

\* §4 the checks of request(src, dst), first failing one wins.
RejectReason(src, dst, act) ==
    IF src \notin act THEN "source_inactive"
    ELSE IF Parent[src] # Parent[dst] THEN "cross_level"
    ELSE IF dst \in act /\ dst # src THEN "target_active"
    ELSE "ok"

\* The effect of request(src, dst) on the active set and its call log.
Transition(src, dst, act) ==
    LET reason == RejectReason(src, dst, act)
        ex == LeaveSeq("exit", src, act)
        en == EnterSeq(dst)
    IN IF reason # "ok" THEN [result |-> reason, active |-> act, log |-> <<>>]
       ELSE [result |-> "ok", active |-> (act \ StatesOf(ex)) \cup StatesOf(en), log |-> ex \o en]

ChainInit ==
    /\ active = StatesOf(EnterSeq(Root))
    /\ log = EnterSeq(Root)
    /\ result = "ok"
    /\ request = [src |-> Root, dst |-> Root]

Request(src, dst) ==
    LET t == Transition(src, dst, active) IN
    /\ active' = t.active
    /\ log' = t.log
    /\ result' = t.result
    /\ request' = [src |-> src, dst |-> dst]

RunScan ==
    /\ log' = LeaveSeq("run", Root, active)
    /\ result' = "ok"
    /\ UNCHANGED <<active, request>>

\* Nested \E: `\E src, dst \in States` makes safestate check over-count states
\* generated (13x here) against TLC; see the report.
ChainNext == RunScan \/ \E src \in States : \E dst \in States : Request(src, dst)

Spec == ChainInit /\ [][ChainNext]_chainVars

-----------------------------------------------------------------------------
\* SCH-01, SCH-02: the active set a set of the tree's states, the result of the last
\* request ok or one of the SCH-02 reject reasons, the last request a pair of states.
TypeOK ==
    /\ active \subseteq States
    /\ result \in {"ok", "source_inactive", "cross_level", "target_active"}
    /\ request \in [src : States, dst : States]

Kinds(k) == {i \in DOMAIN log : log[i].kind = k}

\* SCH-01: the root is active from power-up on.
INV_SCH01_ROOT_ACTIVE == Root \in active
\* SCH-01: an active state's parent is active.
INV_SCH01_PARENT_ACTIVE == \A s \in active : s = Root \/ Parent[s] \in active
\* SCH-01: one active leaf per active sub-chain.
INV_SCH01_ONE_LEAF ==
    \A s \in active \ ParallelStates :
        Children(s) # {} => Cardinality(Children(s) \cap active) = 1
\* SCH-01: entry functions top-down.
INV_SCH01_ENTRY_TOP_DOWN ==
    \A i, j \in Kinds("entry") : i < j => ~IsAncestor(log[j].state, log[i].state)
\* SCH-01: exit functions bottom-up, every exit before every entry.
INV_SCH01_EXIT_BOTTOM_UP ==
    /\ \A i, j \in Kinds("exit") : i < j => ~IsAncestor(log[i].state, log[j].state)
    /\ \A i \in Kinds("exit"), j \in Kinds("entry") : i < j
\* SCH-02: only siblings; a rejected request calls nothing.
INV_SCH02_SIBLINGS_ONLY ==
    /\ (result = "ok" /\ Kinds("exit") # {}) => Parent[request.src] = Parent[request.dst]
    /\ result # "ok" => log = <<>>
\* SCH-02: a self-transition exits and re-enters its state.
INV_SCH02_SELF_REENTERS ==
    (result = "ok" /\ Kinds("exit") # {} /\ request.src = request.dst) =>
        /\ \E i \in Kinds("exit") : log[i].state = request.src
        /\ \E j \in Kinds("entry") : log[j].state = request.src
        /\ request.src \in active
\* SCH-03: sub-chains active iff their starting state is.
INV_SCH03_PARALLEL ==
    \A p \in ParallelStates : \A c \in Children(p) : (c \in active) <=> (p \in active)
\* SCH-04: a scan runs each active state once, each before its parent.
INV_SCH04_RUN_LEAF_TO_ROOT ==
    Kinds("run") # {} =>
        /\ StatesOf(log) = active
        /\ Len(log) = Cardinality(active)
        /\ \A i, j \in Kinds("run") : i < j => ~IsAncestor(log[i].state, log[j].state)

(* Reachability witnesses (non-vacuity): each Witness_X is the negation of a *)
(* situation its invariant is about; checking it as an invariant must fail. *)
Witness_DeepActive == \A s \in active : Children(s) = {} => Parent[s] = Root  \* ONE_LEAF, PARENT_ACTIVE
Witness_ParallelExited == ~(\E p \in ParallelStates : \E i \in Kinds("exit") : log[i].state = p)  \* EXIT, PARALLEL
Witness_NestedEntry == Cardinality(Kinds("entry")) < 4  \* ENTRY_TOP_DOWN
Witness_CrossRejected == result # "cross_level"  \* SIBLINGS_ONLY
Witness_SelfTransition == ~(result = "ok" /\ request.src = request.dst /\ Kinds("exit") # {} /\ request.src # Root)  \* SELF_REENTERS
Witness_RunNested == Cardinality(Kinds("run")) < 6  \* RUN_LEAF_TO_ROOT
===============================================================================
