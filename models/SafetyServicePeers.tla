------------------------- MODULE SafetyServicePeers -------------------------
(***************************************************************************)
(* SAF-01 .. SAF-04 with the environment made explicit: the Safety service *)
(* of SafetyService.tla (unchanged: one step = one cycle), the Safety       *)
(* Client with its E-stop button, the Subsystem State service's access     *)
(* control with a component of higher authority that can seize control,   *)
(* and a lossy, duplicating channel between them.  SafetyService.tla lets  *)
(* any message arrive in any cycle; this module checks the same invariants *)
(* against the concrete peers and shows the protocol's situations          *)
(* reachable (control granted, refused, seized, a lost release).           *)
(* Hardware faults and health errors are left to SafetyService.tla (they   *)
(* do not involve the peers' protocol) to keep the state space small.      *)
(***************************************************************************)
EXTENDS SafetyService

VARIABLES
    button,    \* the Safety Client's E-stop: "RELEASED" or "PRESSED"
    previous,  \* the button in the previous cycle (what a late duplicate carries)
    holder,    \* who holds control at the access control: "NOBODY", "SAF", "OTHER"
    answer     \* the access control's last answer, still in flight (duplicable):
               \* "NONE", "ACCEPTED", "REFUSED", "OTHER" (control seized)

peerVars == <<button, previous, holder, answer>>
PeersView == <<View, peerVars>>

Report(b) == IF b = "PRESSED" THEN "SET" ELSE "CLEAR"

\* What reaches the service in one cycle: the client's Set Estop (lost, fresh,
\* or a late duplicate of the previous one), a health summary (lost or
\* NORMAL), the answer in flight (lost or delivered, again and again), or a
\* Report Control answering a Query Control (naming us iff we hold control).
PeerInboxes ==
    [estop: {"NONE", Report(button), Report(previous)},
     health: {"NONE", "NORMAL"},
     control: {"NONE", answer, IF holder = "SAF" THEN "ACCEPTED" ELSE "OTHER"},
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

\* One cycle: the service cycles on what arrives; then one thing happens in
\* the environment: its Request Control reaches the access control
\* ("DELIVER") or is lost ("LOSE"), or it is delivered and the other
\* component then seizes control ("SEIZE", higher authority) or leaves it
\* ("LEAVE"); and the button may change.
PeersNext ==
    \E in \in PeerInboxes, b \in {"RELEASED", "PRESSED"},
       env \in {"DELIVER", "LOSE", "SEIZE", "LEAVE"} :
        LET r == AfterRequest(IF env = "LOSE" THEN "NONE" ELSE AfterCycle(in).out_request,
                              holder)
        IN /\ Cycle(in)
           /\ button' = b
           /\ previous' = button
           /\ holder' = IF env = "SEIZE" THEN "OTHER"
                        ELSE IF env = "LEAVE" /\ r.holder = "OTHER" THEN "NOBODY"
                        ELSE r.holder
           /\ answer' = IF env = "SEIZE" /\ r.holder = "SAF" THEN "OTHER"
                        ELSE IF r.answer # "NONE" THEN r.answer
                        ELSE answer

PeersTypeOK ==
    /\ TypeOK
    /\ button \in {"RELEASED", "PRESSED"} /\ previous \in {"RELEASED", "PRESSED"}
    /\ holder \in {"NOBODY", "SAF", "OTHER"}
    /\ answer \in {"NONE", "ACCEPTED", "REFUSED", "OTHER"}

(* Witnesses of the protocol's situations (each violated = reachable).     *)
Witness_PeersGranted ==
    ~(button = "PRESSED" /\ state = "EMERGENCY" /\ control = "HELD" /\ holder = "SAF")
Witness_PeersRefused ==
    ~(state = "EMERGENCY" /\ control = "REFUSED" /\ holder = "OTHER")
Witness_PeersLostRelease ==    \* K10 sends the release again
    ~(state = "OPERATIONAL" /\ holder = "SAF" /\ out_request = "RELEASE" /\ estop_age > 0)
=============================================================================
