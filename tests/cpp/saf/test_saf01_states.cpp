// SPDX-License-Identifier: Apache-2.0
// SAF-01: states PAIRING, OPERATIONAL, EMERGENCY, FAULT; PAIRING waits for the first
// Set Estop and raises EMERGENCY meanwhile; FAULT is absorbing.
#include "saf_test_support.hpp"

namespace safestate::saf::test {
namespace {

TEST(SAF01_States, ConstructedInPairingWithNothingReceived) {
  SafetyService s{kSmall, 225};
  Observable constructed{};
  constructed.set_age = kSmall.message_interval;  // no Set Subsystem State(EMERGENCY) sent yet
  EXPECT_EQ(s.observe(), constructed);
  EXPECT_EQ(s.observe().state, SafState::Pairing);
}

TEST(SAF01_States, PairingRaisesEmergencyWhileWaitingForSetEstop) {
  SafetyService s{kSmall, 225};
  CycleResult r = run(s, {});
  EXPECT_EQ(r.state_row, "P03");
  EXPECT_EQ(r.control_row, "K01");
  const Message* req = find(r.outbox, MessageId::RequestControl);
  ASSERT_NE(req, nullptr);
  EXPECT_EQ(req->action, ControlAction::Request);
  EXPECT_EQ(req->authority, 225);
  EXPECT_EQ(s.observe().control, ControlStatus::Requested);
  r = run(s, {accepted()});
  EXPECT_EQ(s.observe().state, SafState::Pairing);
  EXPECT_EQ(s.observe().control, ControlStatus::Held);
  const Message* set = find(r.outbox, MessageId::SetSubsystemState);
  ASSERT_NE(set, nullptr);
  EXPECT_EQ(set->subsystem_state, SubsystemState::Emergency);
}

TEST(SAF01_States, PairingStaysWithoutSetEstop) {
  SafetyService s{kSmall, 225};
  for (int i = 0; i < 3; ++i) (void)run(s, {health(Health::Normal)});
  EXPECT_EQ(s.observe().state, SafState::Pairing);
}

TEST(SAF01_States, FaultIsAbsorbing) {
  SafetyService s = operational();
  CycleResult r = run(s, {clear(), health(Health::Normal)}, true);
  EXPECT_EQ(r.state_row, "E01");
  EXPECT_EQ(s.observe().state, SafState::Fault);
  EXPECT_EQ(s.observe().control, ControlStatus::Requested);
  for (int i = 0; i < 50; ++i) {
    r = run(s, {clear(), health(Health::Normal), accepted()});
    EXPECT_EQ(r.state_row, "F01");
    EXPECT_EQ(s.observe().state, SafState::Fault);
    EXPECT_NE(s.observe().control, ControlStatus::Released);
    EXPECT_EQ(find(r.outbox, MessageId::RequestControl) == nullptr ||
                  find(r.outbox, MessageId::RequestControl)->action == ControlAction::Request,
              true);
  }
}

TEST(SAF01_States, InvalidConfigConstructsInFault) {
  Config c{};
  c.cycle_interval_s = 0.0;
  SafetyService s{c};
  EXPECT_EQ(s.config_error(), ConfigError::CycleIntervalInvalid);
  EXPECT_EQ(s.observe().state, SafState::Fault);
  (void)run(s, {clear()});
  EXPECT_EQ(s.observe().state, SafState::Fault);
  EXPECT_EQ(s.observe().control, ControlStatus::Requested);
}

TEST(SAF01_States, ZeroCycleTimerConstructsInFault) {
  SafetyService s{Timing{2, 40, 0, 20}, 225};
  EXPECT_EQ(s.config_error(), ConfigError::TimeInvalid);
  EXPECT_EQ(s.observe().state, SafState::Fault);
  for (int i = 0; i < 30; ++i) (void)run(s, {clear()});  // no division by a zero interval
  EXPECT_EQ(s.observe().state, SafState::Fault);
}

}  // namespace
}  // namespace safestate::saf::test
