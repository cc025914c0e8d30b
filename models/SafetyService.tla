---------------------------- MODULE SafetyService ----------------------------
(***************************************************************************)
(* SAF-01 .. SAF-04: the Safety service of a JAUS-style robot subsystem    *)
(* (docs/design/safety-service.md, "the page").  One step of this model is *)
(* one call of SafetyService::cycle(): the intake of the cycle's datagrams *)
(* (page section 5: sender and freshness classification, then decoding),   *)
(* the state rows F01..M02 (section 6, transitions A-E) and the control    *)
(* rows K01..K10 with the re-send of section 7.                            *)
(*                                                                         *)
(* Environment.  In every cycle any combination of datagrams may arrive    *)
(* (or none): at most one of each kind, each from the configured peer and  *)
(* fresh, or forged: sent from another address ("_SPOOFED"), or a replay   *)
(* of an earlier Set Estop whose sequence number is outside the replay     *)
(* window ("_REPLAYED").  This contains a lossy, duplicating, reordering   *)
(* channel, a Safety Client that stops sending, a local attacker, and an   *)
(* access control that grants, refuses, or hands control to a component of *)
(* higher authority at any time.                                           *)
(*                                                                         *)
(* Properties over the messages in and out (page section 11) read history  *)
(* variables (named h_...) that this module computes from the inbox and *)
(* outputs alone, with their own classification of the datagrams, so that *)
(* a defect in the service's intake or rows cannot weaken them.            *)
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

\* The datagrams of one cycle (page section 12): at most one genuine datagram
\* of each kind (from the configured peer, fresh) and at most one forged one.
\* Set Estop CLEAR/SET comes from the Safety Client; Report Health Summary,
\* Confirm Control (ACCEPTED, REFUSED), Report Control (US: holder = our id
\* with our authority; OTHER: another holder or nobody) and Report Subsystem
\* State (OPERATIONAL: any value but EMERGENCY) from the subsystem.  The
\* forged datagram arrives after the genuine ones (it would win): a clear
\* Set Estop from another address (CLEAR_SPOOFED) or the client's own
\* earlier one replayed (CLEAR_REPLAYED: sequence number outside the replay
\* window), a NORMAL health summary, a Confirm Control(ACCEPTED) or a Report
\* Control naming us, from another address.
EstopIn   == {"NONE", "CLEAR", "SET"}
HealthIn  == {"NONE", "NORMAL", "ERROR", "FATAL"}
ControlIn == {"NONE", "ACCEPTED", "REFUSED", "US", "OTHER"}
SubsysIn  == {"NONE", "OPERATIONAL"}
ForgedIn  == {"NONE", "CLEAR_SPOOFED", "CLEAR_REPLAYED", "NORMAL_SPOOFED",
              "ACCEPTED_SPOOFED", "US_SPOOFED"}
\* A hardware fault, a forged datagram or a Report Subsystem State comes
\* with any Set Estop; the other kinds are NONE then (FAULT is absorbing; a
\* forged datagram is rejected whatever else arrives, and conformance adds
\* forged datagrams and subsystem reports to every inbox, page section 12).
Inboxes == {in \in [estop: EstopIn, health: HealthIn, control: ControlIn,
                    subsys: SubsysIn, forged: ForgedIn, hw_fault: BOOLEAN] :
               (in.hw_fault \/ in.forged # "NONE" \/ in.subsys # "NONE")
                 => /\ in.health = "NONE" /\ in.control = "NONE"
                    /\ (in.hw_fault => in.forged = "NONE" /\ in.subsys = "NONE")
                    /\ (in.forged # "NONE" => in.subsys = "NONE")}
NoMessages == [estop |-> "NONE", health |-> "NONE", control |-> "NONE",
               subsys |-> "NONE", forged |-> "NONE", hw_fault |-> FALSE]

Max2(a, b) == IF a >= b THEN a ELSE b
ControlAgeMax == Max2(ReportDataTimeoutCycles, MessageIntervalCycles)

VARIABLES
    state, estop, estop_age, health, health_age,
    control, control_age, out_request, out_set_state,
    alarm,      \* the authority contest is lost (page section 7, K03/K06)
    resend,     \* a re-send of Set Subsystem State(EMERGENCY) is due (section 7)
    set_age     \* cycles since the last Set Subsystem State(EMERGENCY), to MessageIntervalCycles

\* Environment and history (not C++ state): the last inbox, and what the
\* properties of section 11 know from the messages alone.
VARIABLES inbox, ever_faulted,
    h_estop,    \* the last genuine Set Estop: "NONE", "CLEAR", "SET"
    h_silence,  \* cycles since it, to EstopTimeoutCycles
    h_health,   \* the last genuine health summary (HealthViews)
    h_health_age, \* cycles since it, to ReportDataTimeoutCycles + 1
    h_told,     \* the last Set Subsystem State sent was EMERGENCY
    h_refused,  \* a genuine refusal since EMERGENCY was last sent or control released
    h_owed,     \* a genuine SET arrived since the subsystem was last told EMERGENCY
    h_held_sent, \* control became HELD and EMERGENCY was sent in that cycle
    h_due,      \* a Report Subsystem State(not EMERGENCY) while held awaits a re-send
    h_due_age,  \* cycles it has waited
    h_ask_age,  \* cycles without Request Control while control is wanted and not held
    h_ask_refused, \* ... counted from a genuine refusal (else from the last request)
    h_released_holding, \* this cycle released control the service held before it
    h_heeded,   \* every access-control message of this cycle was acted on (UCA-2, UCA-6)
    h_held_age, \* cycles control has been held since the grant or the last Report Control(us)
    h_recheck_early, \* held control asked for again before REPORTDATATIMEOUT without cause
    h_set_age,  \* cycles since the last Set Subsystem State(EMERGENCY) to a subsystem held, to Mi
    h_resent_early, \* a re-send of it went out sooner than MESSAGEINTERVAL after the previous one
    shadow      \* the service after this cycle without the forged datagrams

svcVars == <<state, estop, estop_age, health, health_age,
             control, control_age, out_request, out_set_state,
             alarm, resend, set_age>>
histVars == <<ever_faulted, h_estop, h_silence, h_health, h_health_age,
              h_told, h_refused, h_owed, h_held_sent, h_due, h_due_age,
              h_ask_age, h_ask_refused, h_released_holding, h_heeded, h_held_age,
              h_recheck_early, h_set_age, h_resent_early, shadow>>
vars == <<svcVars, inbox, histVars>>

\* The checker and TLC identify states by the service and the history; the
\* last inbox is only a label of the step that produced the state.
View == <<svcVars, histVars>>

Svc == [state |-> state, estop |-> estop, estop_age |-> estop_age,
        health |-> health, health_age |-> health_age, control |-> control,
        control_age |-> control_age, out_request |-> out_request,
        out_set_state |-> out_set_state, alarm |-> alarm, resend |-> resend,
        set_age |-> set_age]

-----------------------------------------------------------------------------
(******************* Intake classification (page section 5) ****************)
\* The transport tags each datagram with its sender (the configured Safety
\* Client, the configured subsystem, or any other address) and its freshness
\* (the Set Estop sequence number inside the replay window); the service
\* accepts a datagram only from the peer of its kind, and only fresh.
SourceOf(v) ==
    IF v \in {"CLEAR_SPOOFED", "NORMAL_SPOOFED", "ACCEPTED_SPOOFED", "US_SPOOFED"}
    THEN "OTHER"
    ELSE IF v \in {"CLEAR", "SET", "CLEAR_REPLAYED"} THEN "CLIENT"
    ELSE "SUBSYSTEM"
FreshOf(v) == v # "CLEAR_REPLAYED"
KindOf(v) ==
    IF v \in {"CLEAR", "SET", "CLEAR_SPOOFED", "CLEAR_REPLAYED"} THEN "estop"
    ELSE IF v \in {"NORMAL", "ERROR", "FATAL", "NORMAL_SPOOFED"} THEN "health"
    ELSE IF v = "OPERATIONAL" THEN "subsys"
    ELSE "control"
ContentOf(v) ==
    IF v \in {"CLEAR_SPOOFED", "CLEAR_REPLAYED"} THEN "CLEAR"
    ELSE IF v = "NORMAL_SPOOFED" THEN "NORMAL"
    ELSE IF v = "ACCEPTED_SPOOFED" THEN "ACCEPTED"
    ELSE IF v = "US_SPOOFED" THEN "US"
    ELSE v
PeerOf(kind) == IF kind = "estop" THEN "CLIENT" ELSE "SUBSYSTEM"
Accepted(v) == v # "NONE" /\ SourceOf(v) = PeerOf(KindOf(v)) /\ FreshOf(v)
\* The content of the message of this kind the service takes from the cycle:
\* the last accepted one (the forged datagram comes last).
Taken(kind, in) ==
    IF in.forged # "NONE" /\ KindOf(in.forged) = kind /\ Accepted(in.forged)
    THEN ContentOf(in.forged)
    ELSE IF Accepted(in[kind]) THEN in[kind] ELSE "NONE"

-----------------------------------------------------------------------------
(************************ Derived conditions (page 4) **********************)
\* SAF-04: ESTOPTIMEOUT in cycles: no Set Estop for EstopTimeoutCycles cycles.
EstopTimedOut(s) == s.estop # "NONE" /\ s.estop_age >= EstopTimeoutCycles
\* SAF-04: REPORTDATATIMEOUT in cycles (ReportDataTimeoutCycles).
HealthBad(s) == \/ s.health \in {"ERROR", "FATAL"}
                \/ s.health_age > ReportDataTimeoutCycles
\* A health summary has been received and is good: "no report yet" is
\* unknown, not healthy (page section 4).
HealthKnownGood(s) == s.health = "NORMAL" /\ s.health_age <= ReportDataTimeoutCycles
Danger(s) == s.estop = "SET" \/ EstopTimedOut(s) \/ HealthBad(s)

-----------------------------------------------------------------------------
(***************************** Intake (page 5) *****************************)
Intake(s, in) ==
    LET e == Taken("estop", in)
        h == Taken("health", in)
    IN
    [s EXCEPT
        !.estop = IF e = "NONE" THEN @ ELSE e,
        !.estop_age = IF e = "NONE"
                      THEN IF @ < EstopTimeoutCycles THEN @ + 1 ELSE @
                      ELSE 0,
        !.health = IF h = "NONE" THEN @ ELSE h,
        !.health_age = IF h = "NONE"
                       THEN IF @ < ReportDataTimeoutCycles + 1 THEN @ + 1 ELSE @
                       ELSE 0,
        !.set_age = IF @ < MessageIntervalCycles THEN @ + 1 ELSE @,
        !.out_request = "NONE",
        !.out_set_state = "NONE"]

\* The control event of the cycle: an accepted Confirm Control or Report
\* Control ("NONE" when none was accepted).
Event(in) == Taken("control", in)
\* An accepted Report Subsystem State other than EMERGENCY.
SubsysNotEmergency(in) == Taken("subsys", in) = "OPERATIONAL"

-----------------------------------------------------------------------------
(********************** State rows, transitions A-E (page 6) **************)
\* "Leave emergency" (A, D): set OPERATIONAL if we hold control, release.
LeaveEmergency(s) ==
    [s EXCEPT !.state = "OPERATIONAL",
              !.out_set_state = IF s.control = "HELD" THEN "OPERATIONAL" ELSE "NONE",
              !.out_request = "RELEASE",
              !.control = "RELEASED",
              !.control_age = 0,
              !.alarm = FALSE]

Enter(s, target) == [s EXCEPT !.state = target]

\* D waits until the subsystem has been told EMERGENCY (control held) or the
\* authority contest is lost (refused): an E-stop shorter than the control
\* round trip still reaches the subsystem (page section 6).
StateRow(s, in) ==
    IF s.state = "FAULT" THEN "F01"
    ELSE IF in.hw_fault THEN "E01"
    ELSE IF s.state = "PAIRING" THEN
        IF s.estop # "NONE" /\ ~Danger(s) /\ HealthKnownGood(s) THEN "P01"
        ELSE IF Danger(s) THEN "P02"
        ELSE "P03"
    ELSE IF s.state = "OPERATIONAL" THEN
        IF EstopTimedOut(s) THEN "O01"
        ELSE IF Danger(s) THEN "O02"
        ELSE "O03"
    ELSE IF /\ s.estop = "CLEAR" /\ ~Danger(s) /\ HealthKnownGood(s)
            /\ s.control \in {"HELD", "REFUSED"} THEN "M01"
    ELSE "M02"

StateStep(s, in) ==
    LET row == StateRow(s, in) IN
    IF row = "E01" THEN Enter(s, "FAULT")
    ELSE IF row \in {"P01", "M01"} THEN LeaveEmergency(s)
    ELSE IF row \in {"P02", "O01", "O02"} THEN Enter(s, "EMERGENCY")
    ELSE s

-----------------------------------------------------------------------------
(*********************** Control rows K01-K10 (page 7) *********************)
\* Confirm Control answers our pending Request Control (control REQUESTED);
\* one we did not ask for is ignored.  Report Control naming us (with our
\* authority) says we hold control whatever we asked.
ControlRow(s, in) ==
    LET ev == Event(in) IN
    IF s.control = "RELEASED" THEN "K01"
    ELSE IF \/ s.control = "REQUESTED" /\ ev = "ACCEPTED"
            \/ s.control \in {"REQUESTED", "REFUSED"} /\ ev = "US" THEN "K02"
    ELSE IF s.control = "REQUESTED" /\ ev = "REFUSED" THEN "K03"
    ELSE IF s.control = "REQUESTED" /\ s.control_age >= ReportDataTimeoutCycles THEN "K04"
    ELSE IF s.control = "REFUSED" /\ s.control_age >= MessageIntervalCycles THEN "K05"
    ELSE IF s.control = "HELD" /\ ev = "OTHER" THEN "K06"
    ELSE IF s.control = "HELD" /\ ev = "US" THEN "K07"
    ELSE IF s.control = "HELD" /\ s.control_age >= ReportDataTimeoutCycles THEN "K08"
    ELSE "K09"

Request(s) == [s EXCEPT !.out_request = "REQUEST", !.control = "REQUESTED",
                        !.control_age = 0]

ControlRows(s, in) ==
    LET row == ControlRow(s, in) IN
    IF row = "K06" THEN [Request(s) EXCEPT !.alarm = TRUE]
    ELSE IF row \in {"K01", "K04", "K05", "K08"} THEN Request(s)
    ELSE IF row = "K02" THEN [s EXCEPT !.control = "HELD", !.control_age = 0,
                                       !.out_set_state = "EMERGENCY",
                                       !.set_age = 0, !.alarm = FALSE]
    ELSE IF row = "K03" THEN [s EXCEPT !.control = "REFUSED", !.control_age = 0,
                                       !.alarm = TRUE]
    ELSE IF row = "K07" THEN [s EXCEPT !.control_age = 0]
    ELSE [s EXCEPT !.control_age = IF @ < ControlAgeMax THEN @ + 1 ELSE @]

\* The re-send (page section 7): a Report Subsystem State other than
\* EMERGENCY while we hold control in an emergency-raising state makes a
\* re-send of Set Subsystem State(EMERGENCY) due; it is sent as soon as
\* MessageIntervalCycles have passed since the last one (deferred, never
\* dropped).  Outside HELD nothing is due and the interval is over.
Resend(s, in) ==
    IF s.control = "HELD" /\ s.out_set_state # "EMERGENCY"
       /\ (s.resend \/ SubsysNotEmergency(in))
    THEN IF s.set_age >= MessageIntervalCycles
         THEN [s EXCEPT !.out_set_state = "EMERGENCY", !.set_age = 0, !.resend = FALSE]
         ELSE [s EXCEPT !.resend = TRUE]
    ELSE IF s.control = "HELD" THEN [s EXCEPT !.resend = FALSE]
    ELSE [s EXCEPT !.resend = FALSE, !.set_age = MessageIntervalCycles]

\* K10 (OPERATIONAL): a Report Control naming us (our release was lost) is
\* answered by releasing again.
ControlStep(s, in) ==
    IF s.state \notin RaisingStates THEN
        LET r == [s EXCEPT !.resend = FALSE, !.set_age = MessageIntervalCycles,
                           !.alarm = FALSE]
        IN IF Event(in) = "US" /\ s.out_request = "NONE"
           THEN [r EXCEPT !.out_request = "RELEASE"] ELSE r
    ELSE Resend(ControlRows(s, in), in)

AfterCycleFrom(s, in) == ControlStep(StateStep(Intake(s, in), in), in)
AfterCycle(in) == AfterCycleFrom(Svc, in)

\* The rows one cycle fires (the C++ CycleResult's state_row and control_row, for
\* the conformance row comparison): the state row on the intake's result, the
\* control row on the state rows' result; in OPERATIONAL only K10, when it fires.
RowsFiredBy(in) ==
    LET s0 == Intake(Svc, in)
        s1 == StateStep(s0, in)
    IN {StateRow(s0, in)} \cup
       IF s1.state \notin RaisingStates
       THEN IF Event(in) = "US" /\ s1.out_request = "NONE" THEN {"K10"} ELSE {}
       ELSE {ControlRow(s1, in)}

-----------------------------------------------------------------------------
SetSvc(s) ==
    /\ state' = s.state /\ estop' = s.estop /\ estop_age' = s.estop_age
    /\ health' = s.health /\ health_age' = s.health_age
    /\ control' = s.control /\ control_age' = s.control_age
    /\ out_request' = s.out_request /\ out_set_state' = s.out_set_state
    /\ alarm' = s.alarm /\ resend' = s.resend /\ set_age' = s.set_age

(* History for the properties of page section 11, from the genuine fields *)
(* of the inbox alone (the forged datagram has its own field), so that a  *)
(* defect in the service's intake cannot hide from them.                  *)
\* The inbox without its forged datagram.
Honest(in) == [in EXCEPT !.forged = "NONE"]

Cycle(in) ==
    LET s == AfterCycle(in)
        told == IF s.out_set_state = "EMERGENCY" THEN TRUE
                ELSE IF s.out_set_state = "OPERATIONAL" THEN FALSE ELSE h_told
        refused == IF s.out_set_state = "EMERGENCY" \/ s.out_request = "RELEASE" THEN FALSE
                   ELSE IF in.control = "REFUSED" THEN TRUE ELSE h_refused
        \* Request Control sent, or not wanted (held, or not raising EMERGENCY)
        asked == \/ s.out_request = "REQUEST" \/ s.control = "HELD"
                 \/ s.state \notin RaisingStates
        due == /\ s.control = "HELD" /\ s.state \in RaisingStates
               /\ s.out_set_state # "EMERGENCY"
               /\ (h_due \/ in.subsys = "OPERATIONAL")
        \* The genuine access-control message of this cycle, read against what
        \* the service had asked before it (UCA-2, UCA-6): a Confirm Control
        \* answering its pending Request Control, or a Report Control naming
        \* another holder while it held control, while EMERGENCY is raised.
        raising == s.state \in RaisingStates
        granted == control = "REQUESTED" /\ in.control = "ACCEPTED"
        refusal == control = "REQUESTED" /\ in.control = "REFUSED"
        taken == control = "HELD" /\ in.control = "OTHER"
        heeded == /\ (raising /\ granted) => s.out_set_state = "EMERGENCY"
                  /\ (raising /\ refusal) => s.alarm
                  /\ (raising /\ taken) => (s.alarm /\ s.out_request = "REQUEST")
                  \* the alarm of a lost contest falls only on a grant
                  /\ (raising /\ alarm /\ ~s.alarm) => (granted \/ in.control = "US")
    IN
    /\ SetSvc(s)
    /\ inbox' = in
    /\ ever_faulted' = (ever_faulted \/ in.hw_fault)
    /\ h_estop' = IF in.estop # "NONE" THEN in.estop ELSE h_estop
    /\ h_silence' = IF in.estop # "NONE" THEN 0
                    ELSE IF h_silence < EstopTimeoutCycles THEN h_silence + 1 ELSE h_silence
    /\ h_health' = IF in.health # "NONE" THEN in.health ELSE h_health
    /\ h_health_age' = IF in.health # "NONE" THEN 0
                       ELSE IF h_health_age <= ReportDataTimeoutCycles
                            THEN h_health_age + 1 ELSE h_health_age
    /\ h_told' = told
    /\ h_refused' = refused
    \* A SET the subsystem has not been told about yet; while control is
    \* refused (the contest lost) it cannot be told.
    /\ h_owed' = IF s.out_set_state = "EMERGENCY" \/ refused THEN FALSE
                 ELSE IF in.estop = "SET" /\ ~told THEN TRUE
                 ELSE h_owed
    /\ h_held_sent' = IF s.control # "HELD" THEN FALSE
                      ELSE IF control # "HELD" THEN s.out_set_state = "EMERGENCY"
                      ELSE h_held_sent
    /\ h_due' = due
    /\ h_due_age' = IF due /\ h_due
                    THEN IF h_due_age < MessageIntervalCycles THEN h_due_age + 1 ELSE h_due_age
                    ELSE 0
    /\ h_ask_age' = IF asked \/ in.control = "REFUSED" THEN 0
                    ELSE IF h_ask_age <= ControlAgeMax THEN h_ask_age + 1 ELSE h_ask_age
    /\ h_ask_refused' = IF asked THEN FALSE
                        ELSE IF in.control = "REFUSED" THEN TRUE ELSE h_ask_refused
    /\ h_released_holding' = (control = "HELD" /\ s.out_request = "RELEASE")
    /\ h_heeded' = heeded
    /\ h_held_age' = IF s.control # "HELD" \/ control # "HELD" \/ in.control = "US" THEN 0
                     ELSE IF h_held_age <= ReportDataTimeoutCycles THEN h_held_age + 1
                     ELSE h_held_age
    \* Request Control while control was held, with no report of another
    \* holder, before REPORTDATATIMEOUT without a Report Control(us).
    /\ h_recheck_early' = /\ control = "HELD" /\ s.out_request = "REQUEST"
                          /\ in.control # "OTHER" /\ h_held_age < ReportDataTimeoutCycles
    /\ h_set_age' = IF s.out_set_state = "EMERGENCY" THEN 0
                    ELSE IF s.control # "HELD" THEN MessageIntervalCycles
                    ELSE IF h_set_age < MessageIntervalCycles THEN h_set_age + 1 ELSE h_set_age
    \* Set Subsystem State(EMERGENCY) again to a subsystem held since before
    \* this cycle (a re-send, not a grant) with fewer than MESSAGEINTERVAL
    \* cycles since the previous one.
    /\ h_resent_early' = /\ control = "HELD" /\ s.control = "HELD"
                         /\ s.out_set_state = "EMERGENCY"
                         /\ h_set_age + 1 < MessageIntervalCycles
    /\ shadow' = IF in.forged = "NONE" THEN s ELSE AfterCycle(Honest(in))

\* Construction: PAIRING, nothing received yet, control not yet requested
\* (the first cycle requests it: K01).
SvcInit == [state |-> "PAIRING", estop |-> "NONE", estop_age |-> 0,
            health |-> "NONE", health_age |-> 0, control |-> "RELEASED",
            control_age |-> 0, out_request |-> "NONE", out_set_state |-> "NONE",
            alarm |-> FALSE, resend |-> FALSE, set_age |-> MessageIntervalCycles]

Init ==
    /\ state = "PAIRING"
    /\ estop = "NONE" /\ estop_age = 0
    /\ health = "NONE" /\ health_age = 0
    /\ control = "RELEASED" /\ control_age = 0
    /\ out_request = "NONE" /\ out_set_state = "NONE"
    /\ alarm = FALSE /\ resend = FALSE /\ set_age = MessageIntervalCycles
    /\ inbox = NoMessages
    /\ ever_faulted = FALSE
    /\ h_estop = "NONE" /\ h_silence = 0
    /\ h_health = "NONE" /\ h_health_age = 0
    /\ h_told = FALSE /\ h_refused = FALSE /\ h_owed = FALSE /\ h_held_sent = FALSE
    /\ h_due = FALSE /\ h_due_age = 0
    /\ h_ask_age = 0 /\ h_ask_refused = FALSE
    /\ h_released_holding = FALSE /\ h_heeded = TRUE
    /\ h_held_age = 0 /\ h_recheck_early = FALSE
    /\ h_set_age = MessageIntervalCycles /\ h_resent_early = FALSE
    /\ shadow = SvcInit

Next == \E in \in Inboxes : Cycle(in)

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(******************************** Invariants *******************************)
\* The values of the service record (Svc, and the shadow service).
SvcRecords == [state: States, estop: EstopViews, estop_age: 0..EstopTimeoutCycles,
               health: HealthViews, health_age: 0..(ReportDataTimeoutCycles + 1),
               control: ControlStatus, control_age: 0..ControlAgeMax,
               out_request: OutRequests, out_set_state: OutSetStates,
               alarm: BOOLEAN, resend: BOOLEAN, set_age: 0..MessageIntervalCycles]

\* SAF-01: every variable in its type; the state one of PAIRING, OPERATIONAL,
\* EMERGENCY, FAULT.
\* Every variable but the inbox in its type (SafetyServicePeers.tla has its own inboxes).
SvcTypeOK ==
    /\ state \in States
    /\ estop \in EstopViews
    /\ estop_age \in 0..EstopTimeoutCycles
    /\ health \in HealthViews
    /\ health_age \in 0..(ReportDataTimeoutCycles + 1)
    /\ control \in ControlStatus
    /\ control_age \in 0..ControlAgeMax
    /\ out_request \in OutRequests
    /\ out_set_state \in OutSetStates
    /\ alarm \in BOOLEAN /\ resend \in BOOLEAN
    /\ set_age \in 0..MessageIntervalCycles
    /\ ever_faulted \in BOOLEAN
    /\ h_estop \in EstopViews /\ h_silence \in 0..EstopTimeoutCycles
    /\ h_health \in HealthViews /\ h_health_age \in 0..(ReportDataTimeoutCycles + 1)
    /\ h_told \in BOOLEAN /\ h_refused \in BOOLEAN /\ h_owed \in BOOLEAN /\ h_held_sent \in BOOLEAN
    /\ h_due \in BOOLEAN /\ h_due_age \in 0..MessageIntervalCycles
    /\ h_ask_age \in 0..(ControlAgeMax + 1) /\ h_ask_refused \in BOOLEAN
    /\ h_released_holding \in BOOLEAN /\ h_heeded \in BOOLEAN
    /\ h_held_age \in 0..(ReportDataTimeoutCycles + 1) /\ h_recheck_early \in BOOLEAN
    /\ h_set_age \in 0..MessageIntervalCycles /\ h_resent_early \in BOOLEAN
    /\ shadow \in SvcRecords

TypeOK == SvcTypeOK /\ inbox \in Inboxes

\* The invariants spell their conditions out from the requirements rather
\* than reuse the operators of the rows above, so that a mutant of a row
\* cannot weaken the invariant that should catch it.

\* INV-SAF-EMERGENCY (SAF-02): whenever the E-stop is set, its messages have
\* timed out, the health is Error/Fatal (or stale) or the hardware is
\* faulted, the service is in EMERGENCY or FAULT and holds (or is requesting)
\* control; it releases control only in OPERATIONAL.
INV_SAF_EMERGENCY ==
    /\ (\/ estop = "SET"
        \/ estop # "NONE" /\ estop_age >= EstopTimeoutCycles
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
    state = "OPERATIONAL" => (estop = "CLEAR" /\ estop_age < EstopTimeoutCycles)

\* SAF-01, SAF-02 (E): FAULT is absorbing, entered on a hardware fault.
INV_SAF_FAULT_ABSORBING ==
    ever_faulted <=> state = "FAULT"

\* SAF-02: Set Subsystem State(EMERGENCY) only with control granted;
\* Set Subsystem State(OPERATIONAL) only when entering OPERATIONAL.
INV_SAF_SET_STATE_WITH_CONTROL ==
    /\ out_set_state = "EMERGENCY" => control = "HELD"
    /\ out_set_state = "OPERATIONAL" => state = "OPERATIONAL"

(* Properties over the messages in and out (page section 11, the unsafe   *)
(* control actions UCA-1..UCA-6 of page section 13).                      *)

\* UCA-1, UCA-2 (SAF-02 B, C, E): a genuine Set Estop(SET), no genuine Set
\* Estop for EstopTimeoutCycles cycles after one, a genuine Error/Fatal
\* health summary or none for more than ReportDataTimeoutCycles cycles, or
\* a hardware fault: in that same cycle the service is in EMERGENCY or
\* FAULT, wants control, and sends no release.
INV_SAF_MSG_EMERGENCY ==
    (\/ h_estop = "SET"
     \/ h_estop # "NONE" /\ h_silence >= EstopTimeoutCycles
     \/ h_health \in {"ERROR", "FATAL"}
     \/ h_health_age > ReportDataTimeoutCycles
     \/ ever_faulted)
    => /\ state \in {"EMERGENCY", "FAULT"}
       /\ control # "RELEASED"
       /\ out_request # "RELEASE"

\* UCA-4 (SAF-02 A, D): OPERATIONAL (and the release of control) only after
\* a genuine clear Set Estop within ESTOPTIMEOUT and a genuine NORMAL health
\* summary within REPORTDATATIMEOUT: no health report yet is unknown.
INV_SAF_MSG_OPERATIONAL ==
    state = "OPERATIONAL" =>
        /\ h_estop = "CLEAR" /\ h_silence < EstopTimeoutCycles
        /\ h_health = "NORMAL" /\ h_health_age <= ReportDataTimeoutCycles

\* UCA-5: a datagram from another address, or a replayed Set Estop, changes
\* nothing: the service equals the one that saw only the genuine datagrams.
INV_SAF_ATTACKER_NO_EFFECT == shadow = Svc

\* UCA-2: granted => sent.  In the cycle control becomes HELD the service
\* sends Set Subsystem State(EMERGENCY) (with INV_SAF_SET_STATE_WITH_CONTROL:
\* sent <=> granted or re-sent while held).
INV_SAF_GRANTED_SENT == control = "HELD" => h_held_sent

\* UCA-3: an E-stop pressed for a single cycle (SET, then CLEAR at once, or
\* alternating every cycle) reaches the subsystem: OPERATIONAL is entered
\* only after Set Subsystem State(EMERGENCY) was sent since the last SET,
\* unless the access control refused us control (the contest, UCA-6).
INV_SAF_NO_SILENT_EMERGENCY == state = "OPERATIONAL" => ~h_owed

\* UCA-2, item 4 of issue 30: a Report Subsystem State other than EMERGENCY
\* while the service holds control in an emergency-raising state (someone
\* changed the subsystem behind its back, or our Set Subsystem State was
\* lost) is answered by Set Subsystem State(EMERGENCY) within
\* MessageIntervalCycles cycles: deferred, never dropped.
INV_SAF_RESEND_BOUNDED == h_due => h_due_age < MessageIntervalCycles

\* UCA-6, the authority contest (page section 7): refused while raising
\* EMERGENCY, the service raises the alarm and asks again within
\* MESSAGEINTERVAL; the alarm stands only while control is not held in an
\* emergency-raising state.
INV_SAF_CONTEST ==
    /\ (control = "REFUSED" /\ state \in RaisingStates)
         => (alarm /\ control_age <= MessageIntervalCycles)
    /\ alarm => (state \in RaisingStates /\ control # "HELD")

\* UCA-6, the contest lost: the service that wants control (it raises
\* EMERGENCY and does not hold control, so the E-stop has not reached the
\* subsystem) sends Request Control again within MESSAGEINTERVAL + 1 cycles
\* of a genuine Confirm Control(REFUSED), and within REPORTDATATIMEOUT + 1
\* cycles of its last unanswered Request Control: a refused service that
\* never asks again leaves the subsystem to the other holder for good.
INV_SAF_ASKS_AGAIN ==
    h_ask_age <= IF h_ask_refused THEN MessageIntervalCycles ELSE ReportDataTimeoutCycles

\* UCA-7: Set Subsystem State(OPERATIONAL) is sent by the holder of control
\* when it releases control, and by nobody else: from a service that does
\* not hold control it would override the EMERGENCY of the component that
\* does (where the subsystem does not enforce its access control), and a
\* holder that releases without it leaves the subsystem in an EMERGENCY no
\* controller will end.  Bound: in the cycle of the release.
INV_SAF_OPERATIONAL_BY_HOLDER ==
    out_set_state = "OPERATIONAL" <=> h_released_holding

\* UCA-2, UCA-6: every access-control message about our control is acted on
\* in its cycle while EMERGENCY is raised: a Confirm Control(ACCEPTED)
\* answering our pending Request Control is answered by Set Subsystem
\* State(EMERGENCY), a Confirm Control(REFUSED) by the alarm, a Report
\* Control naming another holder while we hold control by the alarm and a
\* new Request Control; and the alarm falls only on a grant (a Confirm
\* Control we did not ask for, or none, leaves the contest lost).
INV_SAF_CONTROL_ANSWERED == h_heeded

\* UCA-2: control believed held is checked against the access control: a
\* Request Control goes out at the latest REPORTDATATIMEOUT + 1 cycles after
\* the grant or the last Report Control naming us, and not before
\* REPORTDATATIMEOUT unless another holder was reported (believing too long
\* hides a lost control; doubting early costs a control round trip, during
\* which a due re-send waits for the grant).
INV_SAF_HELD_RECHECKED ==
    /\ control = "HELD" => h_held_age <= ReportDataTimeoutCycles
    /\ ~h_recheck_early

\* UCA-8: Set Subsystem State(EMERGENCY) repeated too soon.  MESSAGEINTERVAL
\* is the seed's pace for messages to the subsystem: a re-send to a
\* subsystem we hold goes out no sooner than MessageIntervalCycles after the
\* previous Set Subsystem State(EMERGENCY) (INV_SAF_RESEND_BOUNDED is the
\* other side: no later than that once due).
INV_SAF_RESEND_PACED == ~h_resent_early

-----------------------------------------------------------------------------
(* Reachability witnesses (non-vacuity): each Witness_X is the negation of *)
(* a situation an invariant speaks about; tests/python/test_saf_model.py   *)
(* checks each alone and expects it violated, i.e. the situation reachable.*)
Witness_EstopSetHeld ==        \* INV_SAF_EMERGENCY, C with control granted
    ~(estop = "SET" /\ state = "EMERGENCY" /\ control = "HELD")
Witness_TimeoutEmergency ==    \* INV_SAF_EMERGENCY, B
    ~(estop = "CLEAR" /\ estop_age >= EstopTimeoutCycles /\ state = "EMERGENCY")
Witness_HealthFatal ==         \* INV_SAF_EMERGENCY, C by health
    ~(health = "FATAL" /\ estop = "CLEAR" /\ state = "EMERGENCY")
Witness_HealthError ==         \* INV_SAF_MSG_EMERGENCY, C by an Error health summary
    ~(health = "ERROR" /\ estop = "CLEAR" /\ state = "EMERGENCY")
Witness_HealthStale ==         \* INV_SAF_EMERGENCY, REPORTDATATIMEOUT
    ~(health_age > ReportDataTimeoutCycles /\ estop = "CLEAR" /\ state = "EMERGENCY")
Witness_Released ==            \* INV_SAF_RELEASE_ONLY_OPERATIONAL, D with control held
    ~(out_request = "RELEASE" /\ out_set_state = "OPERATIONAL")
Witness_Refused ==             \* INV_SAF_RELEASE_ONLY_OPERATIONAL, K03
    ~(state = "EMERGENCY" /\ control = "REFUSED")
Witness_Preempted ==           \* K06: control lost to a higher authority
    ~(state = "EMERGENCY" /\ control = "REQUESTED" /\ alarm)
Witness_Operational ==         \* INV_SAF_NO_OPERATIONAL_IN_DANGER
    ~(state = "OPERATIONAL" /\ estop_age + 1 = EstopTimeoutCycles)
Witness_Fault ==               \* INV_SAF_FAULT_ABSORBING
    ~(ever_faulted /\ control = "HELD")
Witness_SetEmergency ==        \* INV_SAF_SET_STATE_WITH_CONTROL
    ~(out_set_state = "EMERGENCY" /\ state = "PAIRING")
Witness_PairedNoHealth ==      \* INV_SAF_MSG_OPERATIONAL: a clear E-stop, no health yet
    ~(state = "PAIRING" /\ estop = "CLEAR" /\ health = "NONE" /\ estop_age = 0)
Witness_Owed ==                \* INV_SAF_NO_SILENT_EMERGENCY: CLEAR before the grant
    ~(h_owed /\ estop = "CLEAR" /\ state = "EMERGENCY" /\ health = "NORMAL")
Witness_ResendDeferred ==      \* INV_SAF_GRANTED_SENT: a re-send waits for the interval
    ~(resend /\ state = "EMERGENCY" /\ control = "HELD")
Witness_Resent ==              \* INV_SAF_SET_STATE_WITH_CONTROL: a re-send while held
    ~(out_set_state = "EMERGENCY" /\ control = "HELD" /\ control_age > 0)
Witness_ContestAlarm ==        \* INV_SAF_CONTEST
    ~(alarm /\ control = "REFUSED" /\ estop = "SET")
Witness_ReleasedUnheld ==      \* INV_SAF_OPERATIONAL_BY_HOLDER: a release of control lost before, no OPERATIONAL
    ~(out_request = "RELEASE" /\ out_set_state = "NONE" /\ h_told)
Witness_HeldAtRecheck ==       \* INV_SAF_HELD_RECHECKED: held control at the REPORTDATATIMEOUT bound
    ~(control = "HELD" /\ h_held_age = ReportDataTimeoutCycles)
Witness_AskedAfterRefusal ==   \* INV_SAF_ASKS_AGAIN: the bound after a refusal is reached
    ~(h_ask_refused /\ h_ask_age = MessageIntervalCycles)
Witness_AskedAfterSilence ==   \* INV_SAF_ASKS_AGAIN: ... and after an unanswered request
    ~(~h_ask_refused /\ h_ask_age = ReportDataTimeoutCycles /\ control = "REQUESTED")
=============================================================================
