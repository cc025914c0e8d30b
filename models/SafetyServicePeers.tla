------------------------- MODULE SafetyServicePeers -------------------------
(***************************************************************************)
(* SAF-01 .. SAF-04 with the environment made explicit: the Safety service *)
(* of SafetyService.tla (unchanged: one step = one cycle), the Safety       *)
(* Client with its E-stop button, the subsystem with its state and the     *)
(* access control of its Subsystem State service (a component of higher   *)
(* authority can seize control and drive the subsystem OPERATIONAL), a     *)
(* lossy, duplicating channel between them.  SafetyService.tla lets any    *)
(* message (and spoofed and replayed datagrams)                            *)
(* arrive in any cycle; this module checks the same invariants against the *)
(* concrete peers, shows the protocol's situations reachable, and states   *)
(* the end-to-end property over the subsystem's state (page section 13).  *)
(* Hardware faults and health errors are left to SafetyService.tla (they   *)
(* do not involve the peers' protocol) to keep the state space small.      *)
(***************************************************************************)
EXTENDS SafetyService

VARIABLES
    button,    \* the Safety Client's E-stop: "RELEASED" or "PRESSED"
    previous,  \* the button in the previous cycle (what a late duplicate carries)
    holder,    \* who holds control at the access control: "NOBODY", "SAF", "OTHER"
    answer,    \* the access control's last answer, still in flight (duplicable):
               \* "NONE", "ACCEPTED", "REFUSED", "OTHER" (control seized)
    sub_state, \* the subsystem's state: "OPERATIONAL" or "EMERGENCY"
    wrong_age  \* cycles with a delivering channel in which the service has held
               \* control in an emergency-raising state, holds it at the access
               \* control, and the subsystem is not EMERGENCY (to Mi + 2)

peerVars == <<button, previous, holder, answer, sub_state, wrong_age>>
PeersView == <<View, peerVars>>

Report(b) == IF b = "PRESSED" THEN "SET" ELSE "CLEAR"
WrongMax == MessageIntervalCycles + 2

\* What reaches the service in one cycle: the client's Set Estop (lost, fresh,
\* or a late duplicate of the previous one), a NORMAL health summary, the answer in flight (lost or delivered, again and again), or a
\* Report Control answering a Query Control (naming us iff we hold control),
\* the subsystem's Report Subsystem State every cycle (OPERATIONAL when it is;
\* never lost: the end-to-end bound below needs it).  The attacker's
\* datagrams and health errors are left to SafetyService.tla, whose
\* environment has them all, to keep this state space small.
PeerInboxes ==
    [estop: {"NONE", Report(button), Report(previous)},
     health: {"NORMAL"},
     control: {"NONE", answer, IF holder = "SAF" THEN "US" ELSE "OTHER"},
     subsys: {IF sub_state = "OPERATIONAL" THEN "OPERATIONAL" ELSE "NONE"},
     forged: {"NONE"},
     hw_fault: {FALSE}]

\* The access control handles the service's Request Control of this cycle.
AfterRequest(req, h) ==
    IF req = "REQUEST"
    THEN IF h = "OTHER" THEN [holder |-> h, answer |-> "REFUSED"]
         ELSE [holder |-> "SAF", answer |-> "ACCEPTED"]
    ELSE IF req = "RELEASE" /\ h = "SAF" THEN [holder |-> "NOBODY", answer |-> "NONE"]
    ELSE [holder |-> h, answer |-> "NONE"]

PeersInit ==
    /\ Init
    /\ button = "RELEASED" /\ previous = "RELEASED"
    /\ holder = "NOBODY" /\ answer = "NONE"
    /\ sub_state = "OPERATIONAL" /\ wrong_age = 0

\* One cycle: the service cycles on what arrives; then one thing happens in
\* the environment: its messages reach the subsystem ("DELIVER") or are lost
\* ("LOSE"), or they are delivered and the other component then seizes
\* control and sets the subsystem OPERATIONAL ("SEIZE", higher authority) or
\* leaves control ("LEAVE"); and the button may change.  The subsystem
\* obeys Set Subsystem State from the holder of control only.
PeersNext ==
    \E in \in PeerInboxes, b \in {"RELEASED", "PRESSED"},
       env \in {"DELIVER", "LOSE", "SEIZE", "LEAVE"} :
        LET out == AfterCycle(in)
            r == AfterRequest(IF env = "LOSE" THEN "NONE" ELSE out.out_request, holder)
            \* Set Subsystem State goes out before Request Control (page section 8).
            sub == IF env # "LOSE" /\ holder = "SAF" /\ out.out_set_state # "NONE"
                   THEN out.out_set_state
                   ELSE IF env # "LOSE" /\ holder # "SAF" /\ r.holder = "SAF"
                           /\ out.out_set_state = "EMERGENCY"
                   THEN "EMERGENCY"
                   ELSE sub_state
            holder2 == IF env = "SEIZE" THEN "OTHER"
                       ELSE IF env = "LEAVE" /\ r.holder = "OTHER" THEN "NOBODY"
                       ELSE r.holder
            sub2 == IF env = "SEIZE" THEN "OPERATIONAL" ELSE sub
            wrong == /\ out.state \in RaisingStates /\ out.control = "HELD"
                     /\ holder2 = "SAF" /\ sub2 # "EMERGENCY"
        IN /\ Cycle(in)
           /\ button' = b
           /\ previous' = button
           /\ holder' = holder2
           /\ answer' = IF env = "SEIZE" /\ r.holder = "SAF" THEN "OTHER"
                        ELSE IF r.answer # "NONE" THEN r.answer
                        ELSE answer
           /\ sub_state' = sub2
           /\ wrong_age' = IF ~wrong THEN 0
                           ELSE IF env = "LOSE" \/ wrong_age = WrongMax THEN wrong_age
                           ELSE wrong_age + 1

PeersTypeOK ==
    /\ SvcTypeOK
    /\ inbox \in [estop: EstopIn, health: HealthIn, control: ControlIn, subsys: SubsysIn,
                  forged: ForgedIn, hw_fault: BOOLEAN]
    /\ button \in {"RELEASED", "PRESSED"} /\ previous \in {"RELEASED", "PRESSED"}
    /\ holder \in {"NOBODY", "SAF", "OTHER"}
    /\ answer \in {"NONE", "ACCEPTED", "REFUSED", "OTHER"}
    /\ sub_state \in {"OPERATIONAL", "EMERGENCY"}
    /\ wrong_age \in 0..WrongMax

\* UCA-1, UCA-2 end to end (page section 13): while the service holds control
\* in an emergency-raising state and really holds it at the access control,
\* the subsystem is EMERGENCY, or becomes so within MessageIntervalCycles + 1
\* cycles in which the channel delivers (a lost Set Subsystem State is
\* re-sent on the subsystem's report).
PEERS_HELD_MEANS_SUBSYSTEM_EMERGENCY == wrong_age <= MessageIntervalCycles + 1

(* Witnesses of the protocol's situations (each violated = reachable).     *)
Witness_PeersGranted ==
    ~(button = "PRESSED" /\ state = "EMERGENCY" /\ control = "HELD" /\ holder = "SAF"
      /\ sub_state = "EMERGENCY")
Witness_PeersRefused ==
    ~(state = "EMERGENCY" /\ control = "REFUSED" /\ holder = "OTHER")
Witness_PeersLostRelease ==    \* a release while the access control still names us (K10)
    ~(state = "OPERATIONAL" /\ holder = "SAF" /\ out_request = "RELEASE" /\ inbox.control = "US"
      /\ out_set_state = "NONE")
Witness_PeersLostSetResent ==  \* the re-send repairs a lost Set Subsystem State
    ~(out_set_state = "EMERGENCY" /\ control_age > 0 /\ sub_state = "EMERGENCY" /\ holder = "SAF")
=============================================================================
