-------------------- MODULE RuntimeSupervisorProofs --------------------
(***************************************************************************)
(* Strengthening invariant for `safestate prove` (proofs/README.md).      *)
(* INV_SUP_SHUTDOWN_SAFE is not 1-inductive: a state with safety about to *)
(* stop and the outputs not yet safe is unreachable only because the stop *)
(* steps run in StopOrder.  Stop_Progress states that.                     *)
(***************************************************************************)
EXTENDS RuntimeSupervisor

\* StopOrder[stop_step] is evaluated whenever a STOPPED report is taken: the
\* shutdown has started (stop_step >= 1) exactly when the supervisor is
\* shutting down or stopped (the well-definedness obligation of that
\* application, docs/prove.md).
Stop_Started == (stop_step >= 1) <=> sup_state \in {"SHUTTING_DOWN", "STOPPED"}

\* The observer init_age counts the ticks in INIT with the supervisor's own
\* counter (TypeOK bounds it only through the timeout).
Init_Count == sup_state = "INIT" => init_age = init_ticks

Stop_Progress ==
    /\ (stop_step >= 1) <=> sup_state \in {"SHUTTING_DOWN", "STOPPED"}
    /\ stop_step >= 2 => outputs_safe
    /\ \A k \in 2..8 :
           /\ k < stop_step => status[StopOrder[k]] = "STOPPED"
           /\ status[StopOrder[k]] = "STOPPED" => k <= stop_step
=============================================================================
