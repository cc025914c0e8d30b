---------------------------- MODULE SafetyService ----------------------------
(***************************************************************************)
(* SAF-01 .. SAF-04: the Safety service of a JAUS-style robot subsystem    *)
(* (docs/design/safety-service.md, "the page").  One step of this model is *)
(* one call of SafetyService::cycle(): the intake of the cycle's messages  *)
(* (page section 5), the state rows F01..M02 (section 6, transitions A-E)  *)
(* and the control rows K01..K10 (section 7).                              *)
(*                                                                         *)
(* Environment.  The Safety Client, the Subsystem State service with its   *)
(* access control and the channel between them and the service are        *)
(* modelled by their most general behaviour: in every cycle any            *)
(* combination of messages may arrive (or none).  This contains a lossy,   *)
(* duplicating, reordering channel (a lost message is "NONE", a duplicate  *)
(* is the same message again in a later cycle), a Safety Client that stops *)
(* sending or sends garbage (rejected by the codec: "NONE" at this level), *)
(* and an access control that grants, refuses, or hands control to a      *)
(* component of higher authority at any time.  Invariants that hold here   *)
(* hold for every behaviour of the real peers.                             *)
(*                                                                         *)
(* Timeouts are counters with symbolic constants (cycles, page section 3). *)
(***************************************************************************)
EXTENDS Naturals

CONSTANTS
    EstopTimeoutCycles,       \* ESTOPTIMEOUT / CYCLEINTERVAL (default 2)
    ReportDataTimeoutCycles,  \* REPORTDATATIMEOUT / CYCLEINTERVAL (default 40)
    MessageIntervalCycles     \* MESSAGEINTERVAL / CYCLEINTERVAL (default 10)

ASSUME EstopTimeoutCycles      \in Nat \ {0}
ASSUME ReportDataTimeoutCycles \in Nat \ {0}
ASSUME MessageIntervalCycles   \in Nat \ {0}

States       == {"PAIRING", "OPERATIONAL", "EMERGENCY", "FAULT"}
RaisingStates == {"PAIRING", "EMERGENCY", "FAULT"}     \* raise EMERGENCY
EstopViews   == {"NONE", "CLEAR", "SET"}
HealthViews  == {"NONE", "NORMAL", "ERROR", "FATAL"}
ControlStatus == {"RELEASED", "REQUESTED", "REFUSED", "HELD"}
OutRequests  == {"NONE", "REQUEST", "RELEASE"}
OutSetStates == {"NONE", "OPERATIONAL", "EMERGENCY"}

\* The abstract content of one cycle's datagrams (page section 12).
Inboxes == [estop: {"NONE", "CLEAR", "SET"},
            health: {"NONE", "NORMAL", "ERROR", "FATAL"},
            control: {"NONE", "ACCEPTED", "REFUSED", "OTHER"},
            hw_fault: BOOLEAN]
NoMessages == [estop |-> "NONE", health |-> "NONE", control |-> "NONE",
               hw_fault |-> FALSE]

Max2(a, b) == IF a >= b THEN a ELSE b
ControlAgeMax == Max2(ReportDataTimeoutCycles, MessageIntervalCycles)

VARIABLES
    state, estop, estop_age, health, health_age,
    control, control_age, out_request, out_set_state

\* Environment and history (not C++ state).
VARIABLES inbox, ever_faulted

svcVars == <<state, estop, estop_age, health, health_age,
             control, control_age, out_request, out_set_state>>
vars == <<svcVars, inbox, ever_faulted>>

\* The checker and TLC identify states by the service and the history; the
\* last inbox is only a label of the step that produced the state.
View == <<svcVars, ever_faulted>>

Svc == [state |-> state, estop |-> estop, estop_age |-> estop_age,
        health |-> health, health_age |-> health_age, control |-> control,
        control_age |-> control_age, out_request |-> out_request,
        out_set_state |-> out_set_state]

-----------------------------------------------------------------------------
(************************ Derived conditions (page 4) **********************)
\* SAF-04: ESTOPTIMEOUT in cycles (EstopTimeoutCycles = ESTOPTIMEOUT / CYCLEINTERVAL).
EstopTimedOut(s) == s.estop # "NONE" /\ s.estop_age > EstopTimeoutCycles
\* SAF-04: REPORTDATATIMEOUT in cycles (ReportDataTimeoutCycles).
HealthBad(s) == \/ s.health \in {"ERROR", "FATAL"}
                \/ s.health_age > ReportDataTimeoutCycles
Danger(s) == s.estop = "SET" \/ EstopTimedOut(s) \/ HealthBad(s)

-----------------------------------------------------------------------------
(***************************** Intake (page 5) *****************************)
Intake(s, in) ==
    [s EXCEPT
        !.estop = IF in.estop = "NONE" THEN @ ELSE in.estop,
        !.estop_age = IF in.estop = "NONE"
                      THEN IF @ < EstopTimeoutCycles + 1 THEN @ + 1 ELSE @
                      ELSE 0,
        !.health = IF in.health = "NONE" THEN @ ELSE in.health,
        !.health_age = IF in.health = "NONE"
                       THEN IF @ < ReportDataTimeoutCycles + 1 THEN @ + 1 ELSE @
                       ELSE 0,
        !.out_request = "NONE",
        !.out_set_state = "NONE"]

-----------------------------------------------------------------------------
(********************** State rows, transitions A-E (page 6) **************)
\* "Leave emergency" (A, D): set OPERATIONAL if we hold control, release.
LeaveEmergency(s) ==
    [s EXCEPT !.state = "OPERATIONAL",
              !.out_set_state = IF s.control = "HELD" THEN "OPERATIONAL" ELSE "NONE",
              !.out_request = "RELEASE",
              !.control = "RELEASED",
              !.control_age = 0]

Enter(s, target) == [s EXCEPT !.state = target]

StateRow(s, in) ==
    IF s.state = "FAULT" THEN "F01"
    ELSE IF in.hw_fault THEN "E01"
    ELSE IF s.state = "PAIRING" THEN
        IF s.estop # "NONE" /\ ~Danger(s) THEN "P01"
        ELSE IF Danger(s) THEN "P02"
        ELSE "P03"
    ELSE IF s.state = "OPERATIONAL" THEN
        IF EstopTimedOut(s) THEN "O01"
        ELSE IF Danger(s) THEN "O02"
        ELSE "O03"
    ELSE IF s.estop = "CLEAR" /\ ~Danger(s) THEN "M01"
    ELSE "M02"

StateStep(s, in) ==
    LET row == StateRow(s, in) IN
    IF row = "E01" THEN Enter(s, "FAULT")
    ELSE IF row \in {"P01", "M01"} THEN LeaveEmergency(s)
    ELSE IF row \in {"P02", "O01", "O02"} THEN Enter(s, "EMERGENCY")
    ELSE s

-----------------------------------------------------------------------------
(*********************** Control rows K01-K10 (page 7) *********************)
ControlRow(s, in) ==
    IF s.control = "RELEASED" THEN "K01"
    ELSE IF s.control \in {"REQUESTED", "REFUSED"} /\ in.control = "ACCEPTED" THEN "K02"
    ELSE IF s.control = "REQUESTED" /\ in.control = "REFUSED" THEN "K03"
    ELSE IF s.control = "REQUESTED" /\ s.control_age >= ReportDataTimeoutCycles THEN "K04"
    ELSE IF s.control = "REFUSED" /\ s.control_age >= MessageIntervalCycles THEN "K05"
    ELSE IF s.control = "HELD" /\ in.control = "OTHER" THEN "K06"
    ELSE IF s.control = "HELD" /\ in.control = "ACCEPTED" THEN "K07"
    ELSE IF s.control = "HELD" /\ s.control_age >= ReportDataTimeoutCycles THEN "K08"
    ELSE "K09"

Request(s) == [s EXCEPT !.out_request = "REQUEST", !.control = "REQUESTED",
                        !.control_age = 0]

\* K10 (OPERATIONAL): a report that we still hold control (our release was
\* lost, or a stale Confirm Control) is answered by releasing again.
ControlStep(s, in) ==
    IF s.state \notin RaisingStates THEN
        IF in.control = "ACCEPTED" /\ s.out_request = "NONE"
        THEN [s EXCEPT !.out_request = "RELEASE"] ELSE s
    ELSE
    LET row == ControlRow(s, in) IN
    IF row \in {"K01", "K04", "K05", "K06", "K08"} THEN Request(s)
    ELSE IF row = "K02" THEN [s EXCEPT !.control = "HELD", !.control_age = 0,
                                       !.out_set_state = "EMERGENCY"]
    ELSE IF row = "K03" THEN [s EXCEPT !.control = "REFUSED", !.control_age = 0]
    ELSE IF row = "K07" THEN [s EXCEPT !.control_age = 0]
    ELSE [s EXCEPT !.control_age = IF @ < ControlAgeMax THEN @ + 1 ELSE @]

AfterCycle(in) == ControlStep(StateStep(Intake(Svc, in), in), in)

\* The rows one cycle fires (the C++ CycleResult's state_row and control_row, for
\* the conformance row comparison): the state row on the intake's result, the
\* control row on the state rows' result; in OPERATIONAL only K10, when it fires.
RowsFiredBy(in) ==
    LET s0 == Intake(Svc, in)
        s1 == StateStep(s0, in)
    IN {StateRow(s0, in)} \cup
       IF s1.state \notin RaisingStates
       THEN IF in.control = "ACCEPTED" /\ s1.out_request = "NONE" THEN {"K10"} ELSE {}
       ELSE {ControlRow(s1, in)}

-----------------------------------------------------------------------------
SetSvc(s) ==
    /\ state' = s.state /\ estop' = s.estop /\ estop_age' = s.estop_age
    /\ health' = s.health /\ health_age' = s.health_age
    /\ control' = s.control /\ control_age' = s.control_age
    /\ out_request' = s.out_request /\ out_set_state' = s.out_set_state

Cycle(in) ==
    LET s == AfterCycle(in) IN
    /\ SetSvc(s)
    /\ inbox' = in
    /\ ever_faulted' = (ever_faulted \/ in.hw_fault)

\* Construction: PAIRING, nothing received yet, control not yet requested
\* (the first cycle requests it: K01).
Init ==
    /\ state = "PAIRING"
    /\ estop = "NONE" /\ estop_age = 0
    /\ health = "NONE" /\ health_age = 0
    /\ control = "RELEASED" /\ control_age = 0
    /\ out_request = "NONE" /\ out_set_state = "NONE"
    /\ inbox = NoMessages
    /\ ever_faulted = FALSE

Next == \E in \in Inboxes : Cycle(in)

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(******************************** Invariants *******************************)
\* SAF-01: every variable in its type; the state one of PAIRING, OPERATIONAL,
\* EMERGENCY, FAULT.
TypeOK ==
    /\ state \in States
    /\ estop \in EstopViews
    /\ estop_age \in 0..(EstopTimeoutCycles + 1)
    /\ health \in HealthViews
    /\ health_age \in 0..(ReportDataTimeoutCycles + 1)
    /\ control \in ControlStatus
    /\ control_age \in 0..ControlAgeMax
    /\ out_request \in OutRequests
    /\ out_set_state \in OutSetStates
    /\ inbox \in Inboxes
    /\ ever_faulted \in BOOLEAN

\* The invariants spell their conditions out from the requirements rather
\* than reuse the operators of the rows above, so that a mutant of a row
\* cannot weaken the invariant that should catch it.

\* INV-SAF-EMERGENCY (SAF-02): whenever the E-stop is set, its messages have
\* timed out, the health is Error/Fatal (or stale) or the hardware is
\* faulted, the service is in EMERGENCY or FAULT and holds (or is requesting)
\* control; it releases control only in OPERATIONAL.
INV_SAF_EMERGENCY ==
    /\ (\/ estop = "SET"
        \/ estop # "NONE" /\ estop_age > EstopTimeoutCycles
        \/ health \in {"ERROR", "FATAL"}
        \/ health_age > ReportDataTimeoutCycles
        \/ ever_faulted)
       => /\ state \in {"EMERGENCY", "FAULT"}
          /\ control \in {"REQUESTED", "REFUSED", "HELD"}
    /\ out_request = "RELEASE" => state = "OPERATIONAL"

\* The state before the first cycle is the constructor's: nothing received,
\* control not requested yet (the first cycle requests it, K01).
Constructed == inbox = NoMessages /\ state = "PAIRING" /\ control = "RELEASED"
                 /\ estop = "NONE" /\ health = "NONE"

\* INV-SAF-EMERGENCY, SAF-02 (A, D): control is released only from
\* OPERATIONAL; in every emergency-raising state it is held or requested
\* (after the first cycle).
INV_SAF_RELEASE_ONLY_OPERATIONAL ==
    /\ out_request = "RELEASE" => state = "OPERATIONAL"
    /\ ~Constructed => (control = "RELEASED" <=> state = "OPERATIONAL")

\* SAF-02 (B, C): never OPERATIONAL while the last Set Estop says emergency
\* or the Set Estop messages have timed out.
INV_SAF_NO_OPERATIONAL_IN_DANGER ==
    state = "OPERATIONAL" => (estop = "CLEAR" /\ estop_age <= EstopTimeoutCycles)

\* SAF-01, SAF-02 (E): FAULT is absorbing, entered on a hardware fault.
INV_SAF_FAULT_ABSORBING ==
    ever_faulted <=> state = "FAULT"

\* SAF-02: Set Subsystem State(EMERGENCY) only with control granted;
\* Set Subsystem State(OPERATIONAL) only when entering OPERATIONAL.
INV_SAF_SET_STATE_WITH_CONTROL ==
    /\ out_set_state = "EMERGENCY" => control = "HELD"
    /\ out_set_state = "OPERATIONAL" => state = "OPERATIONAL"

-----------------------------------------------------------------------------
(* Reachability witnesses (non-vacuity): each Witness_X is the negation of *)
(* a situation an invariant speaks about; tests/python/test_saf_model.py   *)
(* checks each alone and expects it violated, i.e. the situation reachable.*)
Witness_EstopSetHeld ==        \* INV_SAF_EMERGENCY, C with control granted
    ~(estop = "SET" /\ state = "EMERGENCY" /\ control = "HELD")
Witness_TimeoutEmergency ==    \* INV_SAF_EMERGENCY, B
    ~(estop = "CLEAR" /\ estop_age > EstopTimeoutCycles /\ state = "EMERGENCY")
Witness_HealthFatal ==         \* INV_SAF_EMERGENCY, C by health
    ~(health = "FATAL" /\ estop = "CLEAR" /\ state = "EMERGENCY")
Witness_HealthStale ==         \* INV_SAF_EMERGENCY, REPORTDATATIMEOUT
    ~(health_age > ReportDataTimeoutCycles /\ estop = "CLEAR" /\ state = "EMERGENCY")
Witness_Released ==            \* INV_SAF_RELEASE_ONLY_OPERATIONAL, D with control held
    ~(out_request = "RELEASE" /\ out_set_state = "OPERATIONAL")
Witness_Refused ==             \* INV_SAF_RELEASE_ONLY_OPERATIONAL, K03
    ~(state = "EMERGENCY" /\ control = "REFUSED")
Witness_Preempted ==           \* K06: control lost to a higher authority
    ~(state = "EMERGENCY" /\ control = "REQUESTED" /\ inbox.control = "OTHER")
Witness_Operational ==         \* INV_SAF_NO_OPERATIONAL_IN_DANGER
    ~(state = "OPERATIONAL" /\ estop_age = EstopTimeoutCycles)
Witness_Fault ==               \* INV_SAF_FAULT_ABSORBING
    ~(ever_faulted /\ control = "HELD")
Witness_SetEmergency ==        \* INV_SAF_SET_STATE_WITH_CONTROL
    ~(out_set_state = "EMERGENCY" /\ state = "PAIRING")
=============================================================================
