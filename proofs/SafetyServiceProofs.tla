----------------------- MODULE SafetyServiceProofs -----------------------
(***************************************************************************)
(* Strengthening invariants for `safestate prove` (proofs/README.md).     *)
(* The conjunction of the .cfg's invariants, with TypeOK and the lemmas   *)
(* below, is inductive: every INV_SAF_* holds in all reachable states for *)
(* every value of the timeout constants.                                   *)
(***************************************************************************)
EXTENDS SafetyService

\* The invariants of the .cfg support each other: INV_SAF_EMERGENCY needs
\* INV_SAF_FAULT_ABSORBING (a faulted service is in FAULT, never left by
\* M01) and INV_SAF_RELEASE_ONLY_OPERATIONAL (control is wanted in every
\* emergency-raising state).
Strengthen_ALL ==
    /\ INV_SAF_EMERGENCY
    /\ INV_SAF_RELEASE_ONLY_OPERATIONAL
    /\ INV_SAF_NO_OPERATIONAL_IN_DANGER
    /\ INV_SAF_FAULT_ABSORBING
    /\ INV_SAF_SET_STATE_WITH_CONTROL

\* The message-level properties (page section 11) support each other the
\* same way (INV_SAF_MSG_OPERATIONAL needs INV_SAF_MSG_EMERGENCY's health
\* half, INV_SAF_NO_SILENT_EMERGENCY needs INV_SAF_GRANTED_SENT).
Strengthen_MSG ==
    /\ Strengthen_ALL
    /\ INV_SAF_MSG_EMERGENCY
    /\ INV_SAF_MSG_OPERATIONAL
    /\ INV_SAF_ATTACKER_NO_EFFECT
    /\ INV_SAF_GRANTED_SENT
    /\ INV_SAF_NO_SILENT_EMERGENCY
    /\ INV_SAF_RESEND_BOUNDED
    /\ INV_SAF_CONTEST

\* Intake: only genuine datagrams reach the service's views, so its E-stop
\* and health views are the ones the history computes from the messages.
Lemma_VIEWS ==
    /\ estop = h_estop /\ estop_age = h_silence
    /\ health = h_health /\ health_age = h_health_age

\* UCA-3: control is held only after EMERGENCY was sent (and nothing is
\* owed then); a refusal since then clears the debt; the constructor owes
\* nothing (a SET in PAIRING enters EMERGENCY in the same cycle).
Lemma_OWED ==
    /\ control = "HELD" => (h_told /\ ~h_owed)
    /\ h_refused => ~h_owed
    /\ (control = "REFUSED" /\ state \in RaisingStates) => h_refused
    /\ state = "PAIRING" => ~h_owed

\* The re-send: the history's due flag is the service's resend flag, and it
\* has waited no longer than the interval since the last EMERGENCY.
Lemma_RESEND ==
    /\ h_due <=> resend
    /\ h_due => (h_due_age <= set_age /\ set_age < MessageIntervalCycles)
    /\ resend => (control = "HELD" /\ state \in RaisingStates)

\* UCA-6: the history's wait for a Request Control never exceeds the
\* service's control age, which K04 / K05 bound by the timeout / interval.
Lemma_ASK ==
    /\ (state \notin RaisingStates \/ control \in {"HELD", "RELEASED"}) => h_ask_age = 0
    /\ (state \in RaisingStates /\ control = "REQUESTED")
         => (~h_ask_refused /\ h_ask_age <= control_age
             /\ control_age <= ReportDataTimeoutCycles)
    /\ (state \in RaisingStates /\ control = "REFUSED")
         => (h_ask_refused /\ h_ask_age <= control_age
             /\ control_age <= MessageIntervalCycles)

\* UCA-2, UCA-7, UCA-8: the history's age of held control and of the last
\* Set Subsystem State(EMERGENCY) are the service's control_age and set_age
\* (so K08 and the re-send compare what the messages say), and held control
\* is never older than the timeout K08 reacts to.
Lemma_HELD ==
    /\ control = "HELD" => (h_held_age = control_age /\ control_age <= ReportDataTimeoutCycles)
    /\ control # "HELD" => h_held_age = 0
    /\ h_set_age = set_age
    /\ h_released_holding <=> out_set_state = "OPERATIONAL"

Strengthen_LEMMAS ==
    /\ Strengthen_MSG /\ INV_SAF_ASKS_AGAIN
    /\ INV_SAF_OPERATIONAL_BY_HOLDER /\ INV_SAF_CONTROL_ANSWERED
    /\ INV_SAF_HELD_RECHECKED /\ INV_SAF_RESEND_PACED
    /\ Lemma_VIEWS /\ Lemma_OWED /\ Lemma_RESEND /\ Lemma_ASK /\ Lemma_HELD
=============================================================================
