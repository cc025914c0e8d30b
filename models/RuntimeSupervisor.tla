--------------------------- MODULE RuntimeSupervisor ---------------------------
(***************************************************************************)
(* PRO-05: the runtime supervisor of the fan controller                   *)
(* (docs/design/protection.md, "the page", sections 6-9).  One step is one *)
(* tick: the units' reports and the fault inputs of the tick (one         *)
(* environment event), the supervisor rows X01..S02 (section 7), then the  *)
(* dispatch cycle in the fixed order (section 8).                          *)
(*                                                                         *)
(* Environment: in every tick at most one event: a unit becomes ready or  *)
(* fails (or restarts), the fatal fault is raised or cleared, the watchdog *)
(* goes bad or recovers, a shutdown is requested, or - while shutting     *)
(* down - the unit asked to stop reports it (or does not, yet).            *)
(***************************************************************************)
EXTENDS Naturals, Sequences

CONSTANTS InitTimeoutTicks   \* 5 s = 50 ticks of 100 ms

ASSUME InitTimeoutTicks \in Nat \ {0}

SupStates == {"INIT", "RUN", "DEGRADED", "SHUTTING_DOWN", "STOPPED"}
Units == {"timer", "dispatcher", "monitoring", "control", "safety",
          "diagnostics", "comms"}
UnitStatus == {"INIT", "READY", "FAILED", "STOPPED"}
\* The fixed dispatch order (page 8) and the critical AOs.
Order == <<"monitoring", "control", "safety", "diagnostics", "comms">>
AOs == {Order[i] : i \in 1..Len(Order)}
Critical == {"monitoring", "control", "safety", "diagnostics"}
\* Controlled shutdown (page 9): "outputs" is step 1 (outputs to safe state).
StopOrder == <<"outputs", "comms", "diagnostics", "safety", "control",
               "monitoring", "dispatcher", "timer">>

Events == {[kind |-> k, unit |-> u] : k \in {"READY", "FAIL"}, u \in Units}
          \cup {[kind |-> k, unit |-> "none"] :
                k \in {"NONE", "FATAL_SET", "FATAL_CLEAR", "WD_BAD", "WD_OK",
                       "SHUTDOWN", "STOPPED"}}

\* Inputs (the units' reports, the fault inputs) ...
VARIABLES status, fatal_fault, watchdog_ok
\* ... the supervisor and its outputs ...
VARIABLES sup_state, init_ticks, stop_step, outputs_safe, dispatched
\* ... what the safety unit evaluated in the tick ("NONE": not dispatched;
\* "FRESH": the snapshot monitoring took in this tick; "EMPTY": the mailbox,
\* emptied at the start of every dispatch cycle, had no snapshot, which
\* ao_safety evaluates as an invalid sensor) and the output stage ("GATED":
\* it carries what safety's gate chose in this tick; "SAFE": held safe) ...
VARIABLES safety_input, outputs
\* ... and an observer: ticks spent in INIT, counted from the supervisor's
\* state alone (not its timer), for the init-timeout hazard.
VARIABLES init_age
\* ... and two of the input: a shutdown has been requested (latched), and the
\* stop reports taken since (saturating at the length of the stop order).
VARIABLES shutdown_requested, stop_reports

vars == <<status, fatal_fault, watchdog_ok, sup_state, init_ticks, stop_step,
          outputs_safe, dispatched, safety_input, outputs, init_age, shutdown_requested,
          stop_reports>>

-----------------------------------------------------------------------------
(*************************** Environment of a tick **************************)
Live == sup_state \in {"INIT", "RUN", "DEGRADED"}

Enabled(ev) ==
    CASE ev.kind = "READY" -> Live /\ status[ev.unit] \in {"INIT", "FAILED"}
      [] ev.kind = "FAIL"  -> Live /\ status[ev.unit] \in {"INIT", "READY"}
      [] ev.kind \in {"FATAL_SET", "FATAL_CLEAR", "WD_BAD", "WD_OK", "SHUTDOWN"} -> Live
      [] ev.kind = "STOPPED" -> sup_state = "SHUTTING_DOWN"
      [] OTHER -> TRUE

StatusAfter(ev) ==
    CASE ev.kind = "READY" -> [status EXCEPT ![ev.unit] = "READY"]
      [] ev.kind = "FAIL"  -> [status EXCEPT ![ev.unit] = "FAILED"]
      [] ev.kind = "STOPPED" /\ StopOrder[stop_step] # "outputs" ->
             [status EXCEPT ![StopOrder[stop_step]] = "STOPPED"]
      [] OTHER -> status

-----------------------------------------------------------------------------
(************************** Supervisor rows (page 7) ************************)
Fault(st, fatal, wd) == (\E u \in Units : st[u] = "FAILED") \/ fatal \/ ~wd
RecoveryOK(st, fatal, wd) == (\A u \in Units : st[u] = "READY") /\ ~fatal /\ wd

Row(ev, st, fatal, wd) ==
    IF Live /\ ev.kind = "SHUTDOWN" THEN "X01"
    ELSE IF sup_state = "INIT" THEN
        IF RecoveryOK(st, fatal, wd) THEN "I01"
        ELSE IF Fault(st, fatal, wd) THEN "I02"
        ELSE IF init_ticks + 1 >= InitTimeoutTicks THEN "I03"
        ELSE "I04"
    ELSE IF sup_state = "RUN" THEN
        IF Fault(st, fatal, wd) THEN "R01" ELSE "R02"
    ELSE IF sup_state = "DEGRADED" THEN
        IF RecoveryOK(st, fatal, wd) THEN "D01" ELSE "D02"
    ELSE IF sup_state = "SHUTTING_DOWN" THEN
        IF \A u \in Units : st[u] = "STOPPED" THEN "S01" ELSE "S02"
    ELSE "T01"   \* STOPPED: nothing happens any more

StateAfter(row) ==
    CASE row = "X01" -> "SHUTTING_DOWN"
      [] row \in {"I01", "D01"} -> "RUN"
      [] row \in {"I02", "I03", "R01"} -> "DEGRADED"
      [] row = "S01" -> "STOPPED"
      [] OTHER -> sup_state

(*************************** Dispatch (page 8) ******************************)
\* The dispatcher itself is a unit: while it is not READY nothing is dispatched
\* (the runtime's dispatch_gate, dispatcher.hpp).
Dispatchable(s, st, a) ==
    /\ st["dispatcher"] = "READY"
    /\ st[a] = "READY"
    /\ \/ s = "RUN"
       \/ s \in {"DEGRADED", "SHUTTING_DOWN"} /\ a \in Critical

\* Order filtered by Dispatchable, as five slots padded with "none".
\* (SelectSeq(Order, LAMBDA ...) says the same, but `safestate prove` does
\* not translate LAMBDA nor an empty sequence literal, so the dispatched
\* sequence is a fixed-length tuple.)
NoDispatch == <<"none", "none", "none", "none", "none">>
Dispatch(s, st) ==
    LET Keep(acc, i) ==
            IF Dispatchable(s, st, Order[i])
            THEN [slots |-> [acc.slots EXCEPT ![acc.n + 1] = Order[i]], n |-> acc.n + 1]
            ELSE acc
        start == [slots |-> NoDispatch, n |-> 0]
    IN Keep(Keep(Keep(Keep(Keep(start, 1), 2), 3), 4), 5).slots

FatalAfter(ev) == IF ev.kind = "FATAL_SET" THEN TRUE
                  ELSE IF ev.kind = "FATAL_CLEAR" THEN FALSE ELSE fatal_fault
WatchdogAfter(ev) == IF ev.kind = "WD_BAD" THEN FALSE
                     ELSE IF ev.kind = "WD_OK" THEN TRUE ELSE watchdog_ok

\* The row of page section 7 that event ev fires (the C++ reports it; the
\* conformance harness compares them).
RowsFiredBy(ev) == {Row(ev, StatusAfter(ev), FatalAfter(ev), WatchdogAfter(ev))}

\* What safety evaluates in a dispatch cycle d (slots of Dispatch): the
\* snapshot monitoring took before it in the same cycle, or the emptied mailbox.
InSlots(d, a) == \E i \in 1..5 : d[i] = a
SafetyInput(d) ==
    IF ~InSlots(d, "safety") THEN "NONE"
    ELSE IF InSlots(d, "monitoring") THEN "FRESH" ELSE "EMPTY"

Tick(ev) ==
    LET st == StatusAfter(ev)
        fatal == FatalAfter(ev)
        wd == WatchdogAfter(ev)
        row == Row(ev, st, fatal, wd)
        s == StateAfter(row)
        d == Dispatch(s, st)
        safe == outputs_safe \/ (ev.kind = "STOPPED" /\ StopOrder[stop_step] = "outputs") IN
    /\ Enabled(ev)
    /\ status' = st /\ fatal_fault' = fatal /\ watchdog_ok' = wd
    /\ sup_state' = s
    \* Ticks spent in INIT (0 once INIT is left).
    /\ init_ticks' = IF row = "I04" THEN init_ticks + 1 ELSE 0
    \* A stop step is done when its unit reports (the outputs step: control
    \* acknowledges the safe outputs); then the next one is requested.
    /\ outputs_safe' = safe
    /\ stop_step' = IF row = "X01" THEN 1
                    ELSE IF ev.kind = "STOPPED" /\ stop_step < Len(StopOrder)
                         THEN stop_step + 1 ELSE stop_step
    /\ dispatched' = d
    /\ safety_input' = SafetyInput(d)
    \* The output gate is closed at the start of every dispatch cycle; only
    \* safety, on this tick's snapshot, opens it (and after shutdown step 1
    \* control's command is the safe value whatever the gate does).
    /\ outputs' = IF safe \/ SafetyInput(d) # "FRESH" THEN "SAFE" ELSE "GATED"
    /\ init_age' = IF s = "INIT" THEN init_age + 1 ELSE 0
    /\ shutdown_requested' = (shutdown_requested \/ (Live /\ ev.kind = "SHUTDOWN"))
    /\ stop_reports' = IF ev.kind = "STOPPED" /\ stop_reports < Len(StopOrder)
                      THEN stop_reports + 1 ELSE stop_reports

\* Construction: every unit initialising, watchdog fine, nothing dispatched.
Init ==
    /\ status = [u \in Units |-> "INIT"]
    /\ fatal_fault = FALSE /\ watchdog_ok = TRUE
    /\ sup_state = "INIT" /\ init_ticks = 0
    /\ stop_step = 0 /\ outputs_safe = FALSE
    /\ dispatched = NoDispatch
    /\ safety_input = "NONE" /\ outputs = "SAFE" /\ init_age = 0
    /\ shutdown_requested = FALSE /\ stop_reports = 0

Next == \E ev \in Events : Tick(ev)

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(******************************** Invariants *******************************)
TypeOK ==
    /\ status \in [Units -> UnitStatus]
    /\ fatal_fault \in BOOLEAN /\ watchdog_ok \in BOOLEAN
    /\ sup_state \in SupStates
    /\ init_ticks \in 0..InitTimeoutTicks
    /\ stop_step \in 0..Len(StopOrder)
    /\ outputs_safe \in BOOLEAN
    /\ dispatched \in [1..5 -> AOs \cup {"none"}]
    /\ safety_input \in {"NONE", "FRESH", "EMPTY"}
    /\ outputs \in {"GATED", "SAFE"}
    /\ init_age \in 0..InitTimeoutTicks
    /\ shutdown_requested \in BOOLEAN
    /\ stop_reports \in 0..Len(StopOrder)

\* The order of PRO-05, spelled out here (not Order), so that a mutant of
\* the dispatcher's table cannot change what the invariant demands.
Rank(a) == CASE a = "monitoring" -> 1 [] a = "control" -> 2 [] a = "safety" -> 3
             [] a = "diagnostics" -> 4 [] a = "comms" -> 5

\* The invariants spell their conditions out from the requirement rather
\* than reuse the rows' operators, so a mutant of a row cannot weaken them.

\* PRO-05: Run only with every readiness gate passed, no fatal fault and
\* the watchdog fine (after start-up and after recovery alike).
INV_SUP_RUN_GATES ==
    sup_state = "RUN" =>
        /\ \A u \in Units : status[u] = "READY"
        /\ ~fatal_fault
        /\ watchdog_ok

\* PRO-05 (UCA-S4): the init timeout - the supervisor never waits in INIT
\* for the timeout's number of ticks, counted by the observer (a frozen init
\* timer would keep init_ticks small for ever).
INV_SUP_INIT_TIMEOUT ==
    /\ sup_state = "INIT" => init_age < InitTimeoutTicks
    /\ sup_state = "INIT" => init_ticks = init_age

\* PRO-05: in Degraded (and while shutting down) no non-critical event is
\* dispatched; in INIT and STOPPED nothing is.
INV_SUP_DEGRADED_RESTRICTED ==
    /\ sup_state \in {"DEGRADED", "SHUTTING_DOWN"} =>
           \A i \in 1..5 : dispatched[i] \in Critical \cup {"none"}
    /\ sup_state \in {"INIT", "STOPPED"} => dispatched = NoDispatch
    /\ status["dispatcher"] # "READY" => dispatched = NoDispatch
    /\ \A i \in 1..5 : dispatched[i] # "none" => status[dispatched[i]] = "READY"

\* PRO-05: the fixed dispatch order monitoring, control, safety,
\* diagnostics, communications.
INV_SUP_DISPATCH_ORDER ==
    \A i, j \in 1..5 :
        i < j => IF dispatched[j] = "none" THEN TRUE
                 ELSE dispatched[i] # "none" /\ Rank(dispatched[i]) < Rank(dispatched[j])

\* PRO-05 (UCA-S3): controlled shutdown - protection (the safety unit) stops
\* only after the outputs are safe, never before the units it works with
\* (its sensor input, the output path, the dispatcher and the tick), and
\* STOPPED means every unit has stopped.
INV_SUP_SHUTDOWN_SAFE ==
    /\ status["safety"] = "STOPPED" => outputs_safe
    /\ status["safety"] # "STOPPED" =>
           \A u \in {"monitoring", "control", "dispatcher", "timer"} : status[u] # "STOPPED"
    /\ sup_state = "STOPPED" => \A u \in Units : status[u] = "STOPPED"

\* PRO-04/PRO-05 (UCA-S1, UCA-S2): every tick in RUN, DEGRADED and shutting
\* down until safety's own stop step, while the dispatcher and the safety
\* unit are READY, safety is dispatched, on the snapshot monitoring took in
\* the same tick whenever monitoring is READY (a snapshot no older than the
\* tick); it never evaluates an older one.
INV_SUP_PROTECTION_RUNS ==
    /\ (\/ sup_state \in {"RUN", "DEGRADED"}
        \/ sup_state = "SHUTTING_DOWN" /\ status["safety"] # "STOPPED")
       /\ status["dispatcher"] = "READY" /\ status["safety"] = "READY"
       => /\ safety_input # "NONE"
          /\ status["monitoring"] = "READY" => safety_input = "FRESH"
    /\ safety_input = "FRESH" =>
           \E i, j \in 1..5 : i < j /\ dispatched[i] = "monitoring" /\ dispatched[j] = "safety"

\* PRO-05 (UCA-S7): the controlled shutdown happens exactly on request: in the
\* tick of the request (from INIT, RUN or DEGRADED), and never without one.
INV_SUP_SHUTDOWN_ON_REQUEST ==
    sup_state \in {"SHUTTING_DOWN", "STOPPED"} <=> shutdown_requested

\* PRO-05 (UCA-S9): the shutdown advances one step per stop report, in the
\* tick of the report (a sequence stuck at a step leaves units running):
\* while shutting down the supervisor waits for step 1 + reports so far.
INV_SUP_SHUTDOWN_PROGRESS ==
    /\ sup_state \in {"INIT", "RUN", "DEGRADED"} => stop_reports = 0
    /\ sup_state = "SHUTTING_DOWN" => stop_step = 1 + stop_reports

\* PRO-05 (UCA-S8): Degraded (or INIT) is not kept once every readiness gate
\* passes, no fatal fault is present and the watchdog is fine: RUN in the
\* same tick (a controller kept degraded refuses the operator's clear).
INV_SUP_RUN_WHEN_READY ==
    (/\ \A u \in Units : status[u] = "READY"
     /\ ~fatal_fault /\ watchdog_ok /\ ~shutdown_requested) => sup_state = "RUN"

\* PRO-03/PRO-05 (UCA-S5): fail-safe output stage - the outputs carry a
\* regulated value only in a tick in which safety evaluated that tick's
\* snapshot, and never after shutdown step 1; a tick without safety (INIT,
\* a failed dispatcher or safety unit, STOPPED) holds them safe.
INV_SUP_FAIL_SAFE ==
    outputs = "GATED" =>
        /\ safety_input = "FRESH"
        /\ ~outputs_safe
        /\ sup_state \in {"RUN", "DEGRADED", "SHUTTING_DOWN"}

\* PRO-05 (UCA-S10): once the first stop report of a shutdown has come (control's
\* acknowledgement of step 1, outputs to the safe state), the outputs are held safe in
\* that tick and every tick after: the regulated value never comes back while the
\* remaining units stop. Counted from the stop reports (an input), not from the
\* supervisor's step.
INV_SUP_SAFE_FROM_STEP1 == stop_reports >= 1 => outputs_safe /\ outputs = "SAFE"

-----------------------------------------------------------------------------
(* Reachability witnesses (non-vacuity), checked one by one and expected  *)
(* violated by tests/python/test_pro_model.py.                             *)
Witness_Run ==              \* INV_SUP_RUN_GATES, Run with all five AOs dispatched
    ~(sup_state = "RUN" /\ dispatched[5] # "none")
Witness_DegradedFatal ==    \* INV_SUP_RUN_GATES, Degraded by a fatal fault alone
    ~(sup_state = "DEGRADED" /\ fatal_fault /\ watchdog_ok
      /\ \A u \in Units : status[u] = "READY")
Witness_InitTimeout ==      \* INV_SUP_INIT_TIMEOUT, Degraded by the timeout
    ~(sup_state = "DEGRADED" /\ ~fatal_fault /\ watchdog_ok
      /\ \A u \in Units : status[u] # "FAILED")
Witness_DegradedDispatch == \* INV_SUP_DEGRADED_RESTRICTED, comms ready but skipped
    ~(sup_state = "DEGRADED" /\ status["comms"] = "READY" /\ dispatched[4] # "none" /\ dispatched[5] = "none")
Witness_Order ==            \* INV_SUP_DISPATCH_ORDER, a gap in the order
    ~(dispatched = <<"monitoring", "safety", "diagnostics", "none", "none">>)
Witness_SafetyStopped ==    \* INV_SUP_SHUTDOWN_SAFE, protection ended in shutdown
    ~(sup_state = "SHUTTING_DOWN" /\ status["safety"] = "STOPPED")
Witness_AllStopped ==       \* INV_SUP_SHUTDOWN_SAFE, shutdown complete
    ~(sup_state = "STOPPED")
Witness_DegradedProtects == \* INV_SUP_PROTECTION_RUNS, Degraded, safety on a fresh snapshot
    ~(sup_state = "DEGRADED" /\ safety_input = "FRESH" /\ outputs = "GATED")
Witness_BlindSafety ==      \* INV_SUP_PROTECTION_RUNS, monitoring failed: the empty mailbox
    ~(sup_state = "DEGRADED" /\ safety_input = "EMPTY")
Witness_NoDispatcher ==     \* INV_SUP_FAIL_SAFE, dispatcher failed: nothing runs, outputs safe
    ~(sup_state = "DEGRADED" /\ status["dispatcher"] = "FAILED" /\ status["safety"] = "READY"
      /\ outputs = "SAFE")
Witness_ShutdownFromInit == \* INV_SUP_SHUTDOWN_ON_REQUEST, a stop of a controller never ready
    ~(sup_state = "SHUTTING_DOWN" /\ \E u \in Units : status[u] = "INIT")
Witness_WatchdogHolds ==    \* INV_SUP_RUN_WHEN_READY, every gate passed, kept Degraded by the watchdog
    ~(sup_state = "DEGRADED" /\ ~watchdog_ok /\ ~fatal_fault /\ \A u \in Units : status[u] = "READY")
Witness_HalfwayDown ==      \* INV_SUP_SHUTDOWN_PROGRESS, four stop reports taken
    ~(sup_state = "SHUTTING_DOWN" /\ stop_reports = 4)
Witness_ShutdownProtects == \* INV_SUP_FAIL_SAFE, outputs safe, safety still running
    ~(sup_state = "SHUTTING_DOWN" /\ outputs_safe /\ safety_input = "FRESH")
Witness_HeldSafeAfterStep1 == \* INV_SUP_SAFE_FROM_STEP1, step 1 acknowledged, safety still on fresh snapshots
    ~(sup_state = "SHUTTING_DOWN" /\ stop_reports = 2 /\ safety_input = "FRESH")
=============================================================================
