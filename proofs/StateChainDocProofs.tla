------------------------- MODULE StateChainDocProofs -------------------------
(* Proof typing of StateChainDoc for `safestate prove` (proofs/README.md).    *)
(* The model's TypeOK leaves the call log untyped (TLC needs no type); the    *)
(* prover needs its shape and a length bound: at most 16 calls in one step    *)
(* (a self-transition of the root exits <= 10 active states, enters 6).        *)
EXTENDS StateChainDoc

LogEvents == [kind : {"entry", "exit", "run"}, state : States]
ProofTypeOK ==
    /\ TypeOK
    /\ log \in Seq(LogEvents)
    /\ Len(log) <= 16

\* The shape of the active set (SCH-01, SCH-03): each of these alone is not
\* 1-inductive (a state whose active set is not a chain configuration may step
\* anywhere, and its call log may outgrow the bound); together they are.
Strengthen_CHAIN ==
    /\ INV_SCH01_ROOT_ACTIVE
    /\ INV_SCH01_PARENT_ACTIVE
    /\ INV_SCH01_ONE_LEAF
    /\ INV_SCH03_PARALLEL
===============================================================================
