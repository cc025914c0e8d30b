// SPDX-License-Identifier: Apache-2.0
// SAF-02: transitions A-E (design §6), obtaining and releasing control (§7), and
// INV-SAF-EMERGENCY on random message sequences.
#include <random>

#include "saf_test_support.hpp"

namespace safestate::saf::test {
namespace {

TEST(SAF02_TransitionA, FirstClearSetEstopEntersOperationalAndReleases) {
  SafetyService s{kSmall, 225};
  (void)run(s, {});
  (void)run(s, {accepted()});
  CycleResult r = run(s, {clear(), health(Health::Normal)});
  EXPECT_EQ(r.state_row, "P01");
  EXPECT_EQ(s.observe().state, SafState::Operational);
  EXPECT_EQ(s.observe().control, ControlStatus::Released);
  ASSERT_NE(find(r.outbox, MessageId::SetSubsystemState), nullptr);
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState)->subsystem_state, SubsystemState::Operational);
  ASSERT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl)->action, ControlAction::Release);
}

TEST(SAF02_TransitionA, FirstSetEstopWithEmergencyEntersEmergency) {
  SafetyService s{kSmall, 225};
  CycleResult r = run(s, {pressed()});
  EXPECT_EQ(r.state_row, "P02");
  EXPECT_EQ(s.observe().state, SafState::Emergency);
}

TEST(SAF02_TransitionB, SetEstopTimeoutAfterEstopTimeoutCycles) {
  SafetyService s = operational();  // EstopTimeoutCycles = 2
  (void)run(s, {});
  EXPECT_EQ(s.observe().state, SafState::Operational);  // 1 cycle without: tolerated
  CycleResult r = run(s, {});                           // ESTOPTIMEOUT = 2 cycles without a Set Estop: B
  EXPECT_EQ(r.state_row, "O01");
  EXPECT_EQ(s.observe().state, SafState::Emergency);
  EXPECT_EQ(r.control_row, "K01");
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl)->action, ControlAction::Request);
}

TEST(SAF02_TransitionB, GarbageIsNoSetEstop) {
  SafetyService s = operational();
  const std::uint8_t junk[3] = {1, 2, 3};
  for (int i = 0; i < 3; ++i) {
    InboundBatch b{};
    ASSERT_TRUE(b.push(junk, sizeof junk));
    (void)s.cycle(b, false);
  }
  EXPECT_EQ(s.observe().state, SafState::Emergency);
  EXPECT_EQ(s.diagnostics().rejected[static_cast<std::size_t>(DecodeError::Truncated)], 3U);
}

TEST(SAF02_TransitionC, EstopSetRaisesEmergencyInTheSameCycle) {
  SafetyService s = operational();
  CycleResult r = run(s, {pressed()});
  EXPECT_EQ(r.state_row, "O02");
  EXPECT_EQ(s.observe().state, SafState::Emergency);
  r = run(s, {pressed(), accepted()});
  EXPECT_EQ(s.observe().control, ControlStatus::Held);
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState)->subsystem_state, SubsystemState::Emergency);
}

TEST(SAF02_TransitionC, HealthErrorAndFatalRaiseEmergencyWarningDoesNot) {
  for (Health h : {Health::Error, Health::Fatal}) {
    SafetyService s = operational();
    (void)run(s, {clear(), health(h)});
    EXPECT_EQ(s.observe().state, SafState::Emergency) << to_string(h);
  }
  SafetyService s = operational();
  (void)run(s, {clear(), health(Health::Warning)});
  EXPECT_EQ(s.observe().state, SafState::Operational);
}

TEST(SAF02_TransitionC, StaleHealthCountsAsError) {
  SafetyService s = operational();  // ReportDataTimeoutCycles = 3
  for (int i = 0; i < 3; ++i) (void)run(s, {clear()});
  EXPECT_EQ(s.observe().state, SafState::Operational);
  (void)run(s, {clear()});
  EXPECT_EQ(s.observe().state, SafState::Emergency);
  EXPECT_TRUE(s.health_bad());
}

TEST(SAF02_TransitionD, ClearAndHealthyReturnsToOperationalAndReleases) {
  SafetyService s = operational();
  (void)run(s, {pressed()});
  (void)run(s, {pressed(), accepted()});
  CycleResult r = run(s, {pressed(), health(Health::Normal)});
  EXPECT_EQ(r.state_row, "M02");
  r = run(s, {clear(), health(Health::Normal)});
  EXPECT_EQ(r.state_row, "M01");
  EXPECT_EQ(s.observe().state, SafState::Operational);
  EXPECT_EQ(s.observe().out_set_state, OutSetState::Operational);
  EXPECT_EQ(s.observe().out_request, OutRequest::Release);
  EXPECT_EQ(s.observe().control, ControlStatus::Released);
}

TEST(SAF02_TransitionD, NotWhileHealthIsBad) {
  SafetyService s = operational();
  (void)run(s, {clear(), health(Health::Fatal)});
  CycleResult r = run(s, {clear(), health(Health::Fatal)});
  EXPECT_EQ(r.state_row, "M02");
  EXPECT_EQ(s.observe().state, SafState::Emergency);
}

TEST(SAF02_TransitionD, LostReleaseIsSentAgainWhenAReportSaysWeStillHoldControl) {
  SafetyService s = operational();
  CycleResult r = run(s, {clear(), Message::report_control(kSafetyComponentId, 225)});
  EXPECT_EQ(r.control_row, "K10");
  EXPECT_EQ(s.observe().state, SafState::Operational);
  ASSERT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl)->action, ControlAction::Release);
  r = run(s, {clear(), taken_by_other()});
  EXPECT_EQ(r.control_row, "");
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl), nullptr);
}

TEST(SAF02_TransitionE, HardwareFaultWinsOverAClearMessage) {
  SafetyService s{kSmall, 225};
  (void)run(s, {pressed()});
  CycleResult r = run(s, {clear(), health(Health::Normal)}, true);
  EXPECT_EQ(r.state_row, "E01");
  EXPECT_EQ(s.observe().state, SafState::Fault);
}

TEST(SAF02_Control, RefusedIsRetriedEveryMessageInterval) {
  SafetyService s = operational();  // MessageIntervalCycles = 2
  (void)run(s, {pressed()});
  CycleResult r = run(s, {pressed(), refused()});
  EXPECT_EQ(r.control_row, "K03");
  EXPECT_EQ(s.observe().control, ControlStatus::Refused);
  r = run(s, {pressed()});
  EXPECT_EQ(r.control_row, "K09");
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl), nullptr);
  r = run(s, {pressed()});
  EXPECT_EQ(r.control_row, "K09");
  r = run(s, {pressed()});
  EXPECT_EQ(r.control_row, "K05");
  EXPECT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
  EXPECT_EQ(s.observe().state, SafState::Emergency);
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState), nullptr);  // never without control
}

TEST(SAF02_Control, UnansweredRequestIsRepeatedAfterReportDataTimeout) {
  SafetyService s = operational();  // ReportDataTimeoutCycles = 3
  (void)run(s, {pressed()});
  for (int i = 0; i < 3; ++i) EXPECT_EQ(run(s, {pressed()}).control_row, "K09");
  EXPECT_EQ(run(s, {pressed()}).control_row, "K04");
}

TEST(SAF02_Control, ControlTakenByHigherAuthorityIsRequestedAgain) {
  SafetyService s = operational();
  (void)run(s, {pressed()});
  (void)run(s, {pressed(), accepted()});
  CycleResult r = run(s, {pressed(), taken_by_other()});
  EXPECT_EQ(r.control_row, "K06");
  EXPECT_EQ(s.observe().control, ControlStatus::Requested);
  EXPECT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
}

TEST(SAF02_Control, ReportControlNamingUsKeepsControlFresh) {
  SafetyService s = operational();
  (void)run(s, {pressed()});
  (void)run(s, {pressed(), accepted()});
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(run(s, {pressed(), Message::report_control(kSafetyComponentId, 225)}).control_row, "K07");
  }
  EXPECT_EQ(s.observe().control, ControlStatus::Held);
}

TEST(SAF02_Control, SubsystemStateChangedBehindOurBackIsSetAgain) {
  SafetyService s = operational();
  (void)run(s, {pressed()});
  (void)run(s, {pressed(), accepted()});
  (void)run(s, {pressed()});
  CycleResult r = run(s, {pressed(), Message::report_subsystem_state(SubsystemState::Operational)});
  ASSERT_NE(find(r.outbox, MessageId::SetSubsystemState), nullptr);
  EXPECT_EQ(find(r.outbox, MessageId::SetSubsystemState)->subsystem_state, SubsystemState::Emergency);
}

// INV-SAF-EMERGENCY and the other invariants of design §11 after every cycle of a long
// random run (messages of every kind, garbage, hardware faults rarely).
TEST(SAF02_InvSafEmergency, HoldsOnRandomMessageSequences) {
  std::mt19937 rng(20261129);
  for (int run_no = 0; run_no < 200; ++run_no) {
    SafetyService s{kSmall, 225};
    bool ever_faulted = false;
    for (int i = 0; i < 500; ++i) {
      InboundBatch b{};
      const unsigned pick = rng();
      if (pick % 3 == 1) (void)b.push(encode(Message::set_estop(pick % 7 == 0)), Sender::Client);
      if (pick % 5 == 1) (void)b.push(encode(health(static_cast<Health>(rng() % 4))), Sender::Subsystem);
      if (pick % 4 == 1) (void)b.push(encode(rng() % 2 ? accepted() : refused()), Sender::Subsystem);
      if (pick % 11 == 1) (void)b.push(encode(taken_by_other()), Sender::Subsystem);
      if (pick % 17 == 1) (void)b.push(encode(clear()), Sender::Other);  // spoofed: rejected
      if (pick % 13 == 1) {
        const std::uint8_t junk[12] = {0x3C, 1, 0, 0, 1, 0, 0, 0, 1, 0, 9, 9};
        (void)b.push(junk, sizeof junk);
      }
      const bool hw = rng() % 2000 == 0;
      ever_faulted = ever_faulted || hw;
      (void)s.cycle(b, hw);
      const Observable& o = s.observe();
      const bool wants = o.control != ControlStatus::Released;
      if (s.danger() || ever_faulted) {
        ASSERT_TRUE(o.state == SafState::Emergency || o.state == SafState::Fault);
        ASSERT_TRUE(wants);
      }
      ASSERT_EQ(o.state == SafState::Operational, !wants);
      if (o.out_request == OutRequest::Release) {
        ASSERT_EQ(o.state, SafState::Operational);
      }
      if (o.state == SafState::Operational) {
        ASSERT_EQ(o.estop, EstopView::Clear);
      }
      ASSERT_EQ(ever_faulted, o.state == SafState::Fault);
      if (o.out_set_state == OutSetState::Emergency) {
        ASSERT_EQ(o.control, ControlStatus::Held);
      }
    }
  }
}

}  // namespace
}  // namespace safestate::saf::test
