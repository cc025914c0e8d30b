// SPDX-License-Identifier: Apache-2.0
// Issue 30 (design §5, §7, §11, §13): the service against a sender that is not its peer,
// the authority contest, and the logic defects of item 4 (dropped re-send, late E-stop
// timeout, "no health yet" taken as healthy, uncorrelated Confirm Control).
#include "saf_test_support.hpp"

namespace safestate::saf::test {
namespace {

InboundBatch from(Sender peer, const Message& m, bool fresh = true) {
  InboundBatch b{};
  EXPECT_TRUE(b.push(encode(m), peer, fresh));
  return b;
}

/// A service in EMERGENCY holding control (E-stop SET, granted).
SafetyService emergency_held(const Timing& t = kSmall) {
  SafetyService s = operational(t);
  (void)run(s, {pressed(), health(Health::Normal)});
  (void)run(s, {pressed(), accepted()});
  EXPECT_EQ(s.observe().control, ControlStatus::Held);
  return s;
}

// UCA-5: a spoofed or replayed clear Set Estop changes nothing but its counter.
TEST(SAF_Issue30_Attacker, SpoofedAndReplayedClearLeaveEmergency) {
  SafetyService s = emergency_held();
  for (int i = 0; i < 20; ++i) {
    InboundBatch b{};
    ASSERT_TRUE(b.push(encode(pressed()), Sender::Client));
    ASSERT_TRUE(b.push(encode(clear()), Sender::Other));          // another local process
    ASSERT_TRUE(b.push(encode(clear()), Sender::Client, false));  // a replay (stale sequence)
    ASSERT_TRUE(b.push(encode(clear()), Sender::Subsystem));      // the wrong peer
    ASSERT_TRUE(b.push(encode(health(Health::Normal)), Sender::Subsystem));
    (void)s.cycle(b, false);
    ASSERT_EQ(s.observe().state, SafState::Emergency);
    ASSERT_EQ(s.observe().estop, EstopView::Set);
  }
  EXPECT_EQ(s.diagnostics().rejected_source, 40U);
  EXPECT_EQ(s.diagnostics().rejected_stale, 20U);
}

TEST(SAF_Issue30_Attacker, ReplayWithTheClientDeadStillTimesOut) {
  SafetyService s = operational();
  for (int i = 0; i < 2; ++i) (void)s.cycle(from(Sender::Client, clear(), false), false);
  EXPECT_EQ(s.observe().state, SafState::Emergency);
}

// Item 2: forged Confirm / Report Control from another source never make us HELD.
TEST(SAF_Issue30_Attacker, ForgedControlAnswersAreRejected) {
  SafetyService s = operational();
  (void)run(s, {pressed()});
  for (int i = 0; i < 10; ++i) {
    (void)s.cycle(from(Sender::Other, accepted()), false);
    (void)s.cycle(from(Sender::Other, Message::report_control(kSafetyComponentId, 225)), false);
    (void)s.cycle(from(Sender::Client, accepted()), false);
    ASSERT_NE(s.observe().control, ControlStatus::Held);
  }
  EXPECT_EQ(s.diagnostics().rejected_source, 30U);
}

// Item 2, §7: a Confirm Control we did not ask for is ignored and counted.
TEST(SAF_Issue30_Correlation, UnsolicitedConfirmIsIgnoredAndCounted) {
  SafetyService s = operational();
  (void)run(s, {pressed()});
  CycleResult r = run(s, {pressed(), refused()});
  ASSERT_EQ(s.observe().control, ControlStatus::Refused);
  r = run(s, {pressed(), accepted()});  // nothing pending: the refusal answered our request
  EXPECT_EQ(s.observe().control, ControlStatus::Refused);
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState), nullptr);
  EXPECT_EQ(s.diagnostics().unsolicited_confirm, 1U);
  (void)run(s, {pressed(), Message::report_control(kSafetyComponentId, 7)});  // not our authority
  EXPECT_EQ(s.observe().control, ControlStatus::Refused);
  EXPECT_EQ(s.diagnostics().inconsistent_report, 1U);
}

// Item 2, UCA-6: the authority contest: alarm, request again every MESSAGEINTERVAL, stay.
TEST(SAF_Issue30_Contest, LostContestRaisesTheAlarmAndKeepsAsking) {
  SafetyService s = emergency_held();
  CycleResult r = run(s, {pressed(), taken_by_other()});
  EXPECT_EQ(r.control_row, "K06");
  EXPECT_TRUE(s.observe().alarm);
  int requests = 0;
  for (int i = 0; i < 12; ++i) {
    r = run(s, {pressed(), refused()});
    requests += find(r.outbox, MessageId::RequestControl) != nullptr;
    ASSERT_TRUE(s.observe().alarm);
    ASSERT_EQ(s.observe().state, SafState::Emergency);
    ASSERT_EQ(find(r.outbox, MessageId::SetSubsystemState), nullptr);
  }
  EXPECT_GE(requests, 12 / (kSmall.message_interval + 2));  // K03, Mi cycles, K05
  r = run(s, {pressed(), Message::report_control(kSafetyComponentId, 225)});
  EXPECT_EQ(s.observe().control, ControlStatus::Held);
  EXPECT_FALSE(s.observe().alarm);
  ASSERT_NE(find(r.outbox, MessageId::SetSubsystemState), nullptr);  // granted => sent
  EXPECT_GE(s.diagnostics().alarms, 2U);
}

// Item 4: a Report Subsystem State right after our Set Subsystem State(EMERGENCY) defers
// the re-send to MESSAGEINTERVAL instead of dropping it.
TEST(SAF_Issue30_Resend, ReportInsideTheIntervalIsDeferredNotDropped) {
  SafetyService s = emergency_held();  // EMERGENCY sent in this cycle; Mi = 2
  CycleResult r = run(s, {pressed(), Message::report_subsystem_state(SubsystemState::Operational)});
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState), nullptr);
  EXPECT_TRUE(s.observe().resend);
  r = run(s, {pressed()});  // no new report: the due re-send goes out once the interval is over
  ASSERT_NE(find(r.outbox, MessageId::SetSubsystemState), nullptr);
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState)->subsystem_state, SubsystemState::Emergency);
  EXPECT_FALSE(s.observe().resend);
}

TEST(SAF_Issue30_Resend, SubsystemReportedOperationalIsSetAgainEveryInterval) {
  SafetyService s = emergency_held(Timing{2, 40, 10, 20});
  int sent = 0;
  for (int i = 0; i < 100; ++i) {
    const CycleResult r = run(s, {pressed(), health(Health::Normal), Message::report_control(kSafetyComponentId, 225),
                                  Message::report_subsystem_state(SubsystemState::Operational)});
    sent += find(r.outbox, MessageId::SetSubsystemState) != nullptr;
  }
  EXPECT_EQ(sent, 10);  // once every MESSAGEINTERVAL (10 cycles), never dropped
}

// Item 4: the E-stop timeout reacts at ESTOPTIMEOUT; the end-to-end latency at the
// production timings (design §13): state EMERGENCY 100 ms after the last Set Estop's
// cycle, Set Subsystem State(EMERGENCY) in the cycle the grant arrives (+50 ms).
TEST(SAF_Issue30_Latency, TimeoutAndPressAtProductionTimings) {
  SafetyService s{Config{}};
  (void)run(s, {clear(), health(Health::Normal)});
  ASSERT_EQ(s.observe().state, SafState::Operational);
  int cycles = 0;
  CycleResult r{};
  do {
    r = run(s, {health(Health::Normal)});
    ++cycles;
  } while (s.observe().state == SafState::Operational && cycles < 10);
  EXPECT_EQ(cycles, 2);  // 2 x 50 ms = ESTOPTIMEOUT
  EXPECT_EQ(r.state_row, "O01");
  ASSERT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
  r = run(s, {accepted(), health(Health::Normal)});
  ASSERT_NE(find(r.outbox, MessageId::SetSubsystemState), nullptr);  // 150 ms after the last Set Estop

  SafetyService p{Config{}};
  (void)run(p, {clear(), health(Health::Normal)});
  r = run(p, {pressed()});  // the press: EMERGENCY and Request Control in the same cycle
  EXPECT_EQ(p.observe().state, SafState::Emergency);
  ASSERT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
  r = run(p, {pressed(), accepted()});
  ASSERT_NE(find(r.outbox, MessageId::SetSubsystemState), nullptr);
}

// Item 4: "no health report yet" is unknown: a clear Set Estop alone does not pair.
TEST(SAF_Issue30_Health, NoHealthReportYetIsNotHealthy) {
  SafetyService s{Timing{2, 40, 10, 20}, 225};
  for (int i = 0; i < 30; ++i) {
    ASSERT_NE(run(s, {clear()}).state_row, "P01");
    ASSERT_EQ(s.observe().state, SafState::Pairing);
  }
  EXPECT_EQ(run(s, {clear(), health(Health::Normal)}).state_row, "P01");
}

// Item 3, UCA-3: SET and CLEAR alternating every cycle still sets the subsystem EMERGENCY.
TEST(SAF_Issue30_Alternating, SetClearEveryCycleStillSendsEmergency) {
  SafetyService s = operational();
  int emergencies = 0;
  for (int i = 0; i < 40; ++i) {
    const bool set = i % 2 == 0;
    const CycleResult r = run(s, {set ? pressed() : clear(), health(Health::Normal), accepted()});
    const Message* m = find(r.outbox, MessageId::SetSubsystemState);
    if (m != nullptr && m->subsystem_state == SubsystemState::Emergency) ++emergencies;
  }
  EXPECT_GE(emergencies, 10);
}

}  // namespace
}  // namespace safestate::saf::test
