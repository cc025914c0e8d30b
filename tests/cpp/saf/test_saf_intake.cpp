// SPDX-License-Identifier: Apache-2.0
// The intake of design §14 without sockets: the order of its checks, the replay window's
// boundary, the no-reordering choice, the overflow rule (a clear rejected, a set accepted,
// the sequence advanced either way), and the seed's form where a deployment allows it.
#include <gtest/gtest.h>

#include "safestate/saf/intake.hpp"

namespace safestate::saf::test {
namespace {

constexpr Peer kClient{kLoopback, 4000};
constexpr Peer kSubsystem{kLoopback, 4001};
constexpr Peer kOther{kLoopback, 4002};
constexpr std::uint32_t kId = 0x0001'0300;

IntakeConfig config(bool with_key) {
  IntakeConfig c{};
  c.client = kClient;
  c.client_component_id = kId;
  c.subsystem = kSubsystem;
  c.replay_window = 8;
  if (with_key) {
    c.key.size = 20;
    for (std::size_t i = 0; i < c.key.size; ++i) c.key.bytes[i] = static_cast<std::uint8_t>(i + 1);
  }
  return c;
}

Datagram datagram(const Encoded& e) {
  Datagram d{};
  d.size = e.size;
  for (std::size_t i = 0; i < e.size; ++i) d.bytes[i] = e.bytes[i];
  return d;
}

IntakeReason judge(Intake& in, const Encoded& e, const Source& from = {kClient, SocketRole::Client},
                   bool overflow = false) {
  return in.judge(datagram(e), from, overflow).reason;
}

TEST(SAF03_Intake, ReplayWindowSeparatesReplayFromStaleAndNeverReorders) {
  Intake in{config(false)};
  const MacKey none{};
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 100, none)), IntakeReason::None);
  EXPECT_EQ(judge(in, encode_set_estop(true, kId, 101, none)), IntakeReason::None);
  // A clear sent before the set, arriving after it: never applied.
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 100, none)), IntakeReason::EstopReplay);
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 101, none)), IntakeReason::EstopReplay);
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 94, none)), IntakeReason::EstopReplay);  // 101 - 94 = 7 < 8
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 93, none)), IntakeReason::EstopStale);   // 8: outside
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 1'000'000, none)), IntakeReason::None);  // a restarted client
  EXPECT_EQ(in.highest_sequence(), 1'000'000U);
}

TEST(SAF03_Intake, OverflowRejectsAClearButAdvancesItsSequenceAndAcceptsASet) {
  Intake in{config(false)};
  const MacKey none{};
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 10, none), {kClient, SocketRole::Client}, true),
            IntakeReason::EstopClearInOverflow);
  EXPECT_EQ(in.highest_sequence(), 10U);
  EXPECT_EQ(judge(in, encode_set_estop(false, kId, 10, none)), IntakeReason::EstopReplay);  // not after the flood
  EXPECT_EQ(judge(in, encode_set_estop(true, kId, 11, none), {kClient, SocketRole::Client}, true), IntakeReason::None);
}

TEST(SAF03_Intake, SourceIsCheckedBeforeContentAndPerMessageType) {
  Intake in{config(true)};
  const MacKey key = config(true).key;
  const Encoded good = encode_set_estop(false, kId, 5, key);
  EXPECT_EQ(judge(in, good, {kOther, SocketRole::Client}), IntakeReason::EstopWrongSource);
  // With a key the subsystem socket takes only the link's sealed datagrams (design §15): an
  // authenticated Set Estop has the sealed shape, but its MAC is no link MAC.
  EXPECT_EQ(judge(in, good, {kClient, SocketRole::Subsystem}), IntakeReason::ReportBadMac);
  EXPECT_EQ(judge(in, encode(Message::report_health(Health::Normal)), {kSubsystem, SocketRole::Subsystem}),
            IntakeReason::ReportUnauthenticated);
  EXPECT_EQ(judge(in, good), IntakeReason::None);
  const Encoded health = encode(Message::report_health(Health::Normal));
  EXPECT_EQ(
      judge(in, link_seal(health, 1, LinkDirection::SubsystemToService, key), {kSubsystem, SocketRole::Subsystem}),
      IntakeReason::None);
  EXPECT_EQ(judge(in, health, {kSubsystem, SocketRole::Client}), IntakeReason::ReportWrongSource);
  EXPECT_EQ(judge(in, health, {kClient, SocketRole::Client}), IntakeReason::ReportWrongSource);
  // The MAC is checked before the id and the sequence it covers.
  Encoded forged = encode_set_estop(false, 0xBAD, 6, key);
  forged.bytes[kHeaderSize + 1] ^= 0x01U;
  EXPECT_EQ(judge(in, forged), IntakeReason::EstopBadMac);
  EXPECT_EQ(judge(in, encode_set_estop(false, 0xBAD, 6, key)), IntakeReason::EstopWrongComponent);
  EXPECT_EQ(in.highest_sequence(), 5U);  // neither advanced it
  EXPECT_EQ(in.counters().accepted, 2U);
  EXPECT_EQ(in.counters().rejected_total(), 7U);
}

TEST(SAF03_Intake, SeedFormOnlyWhereTheDeploymentAllowsIt) {
  IntakeConfig c = config(false);
  c.require_sequence = false;
  Intake lax{c};
  EXPECT_EQ(judge(lax, encode(Message::set_estop(false))), IntakeReason::None);
  EXPECT_EQ(judge(lax, encode(Message::set_estop(false)), {kClient, SocketRole::Client}, true),
            IntakeReason::EstopClearInOverflow);
  EXPECT_EQ(judge(lax, encode(Message::set_estop(false)), {kOther, SocketRole::Client}),
            IntakeReason::EstopWrongSource);
  Intake strict{config(false)};
  EXPECT_EQ(judge(strict, encode(Message::set_estop(false))), IntakeReason::EstopUnsequenced);
}

TEST(SAF03_Intake, FilterPassesAcceptedDatagramsInOrderWithTheirSources) {
  Intake in{config(false)};
  InboundBatch b{};
  ASSERT_TRUE(b.push(encode(Message::report_health(Health::Error)), {kSubsystem, SocketRole::Subsystem}));
  ASSERT_TRUE(b.push(encode(Message::set_estop(false)), {kOther, SocketRole::Client}));
  ASSERT_TRUE(b.push(encode_set_estop(true, kId, 3, MacKey{}), {kClient, SocketRole::Client}));
  InboundBatch out{};
  const IntakeCycle c = in.filter(b, false, out);
  ASSERT_EQ(out.count, 2U);
  EXPECT_EQ(decode(out.items[0].bytes.data(), out.items[0].size).message.id, MessageId::ReportHealthSummary);
  EXPECT_EQ(decode(out.items[1].bytes.data(), out.items[1].size).message.sequence, 3U);
  EXPECT_EQ(out.sources[1].peer, kClient);
  ASSERT_EQ(c.count, 1U);
  EXPECT_EQ(c.rejected[0].reason, IntakeReason::EstopWrongSource);
  EXPECT_EQ(c.rejected[0].source.peer, kOther);
}

}  // namespace
}  // namespace safestate::saf::test
