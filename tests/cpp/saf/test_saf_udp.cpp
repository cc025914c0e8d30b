// SPDX-License-Identifier: Apache-2.0
// SAF-02/SAF-03 over the real transport (design §9): the service on a UDP socket on the
// loopback interface against the simulated Safety Client and subsystem, and a flood of
// garbage datagrams: bounded work per cycle, everything rejected and counted, the service
// keeps answering every cycle and fails safe (E-stop timeout) while valid messages are
// drowned, and recovers once the flood has drained.
#include <algorithm>
#include <cstdio>

#include "saf_test_support.hpp"
#include "safestate/saf/safety_client_sim.hpp"
#include "safestate/saf/subsystem_sim.hpp"

namespace safestate::saf::test {
namespace {

struct Loopback {
  UdpEndpoint service;
  UdpEndpoint client;
  UdpEndpoint subsystem;
  Loopback() {
    EXPECT_EQ(service.open(0), UdpError::None);
    EXPECT_EQ(client.open(0), UdpError::None);
    EXPECT_EQ(subsystem.open(0), UdpError::None);
  }
};

struct CycleStats {
  std::size_t read = 0;
};

CycleStats cycle(SafetyService& s, UdpEndpoint& ep, SafetyClientSim& c, SubsystemSim& sub) {
  c.step(ep.port());
  sub.step();
  InboundBatch b{};
  CycleStats st{};
  st.read = ep.receive_batch(b);
  tag_by_kind(b);
  const CycleResult r = s.cycle(b, false);
  for (std::size_t i = 0; i < r.outbox.count; ++i) (void)ep.send_to(sub.port(), encode(r.outbox.messages[i]));
  sub.step();
  return st;
}

TEST(SAF02_Udp, EstopOverUdpTakesControlAndSetsEmergency) {
  Loopback net;
  const std::uint16_t service_port = net.service.port();
  SafetyService s{Config{}};
  SafetyClientSim client{std::move(net.client)};
  SubsystemSim sub{std::move(net.subsystem)};
  // Cycle 0 queries the health; OPERATIONAL once the clear Set Estop and a health summary are in.
  for (int i = 0; i < 2; ++i) (void)cycle(s, net.service, client, sub);
  EXPECT_EQ(s.observe().state, SafState::Operational);
  client.set_mode(ClientMode::Emergency);
  for (int i = 0; i < 3; ++i) (void)cycle(s, net.service, client, sub);
  EXPECT_EQ(s.observe().state, SafState::Emergency);
  EXPECT_EQ(s.observe().control, ControlStatus::Held);
  EXPECT_EQ(sub.state(), SubsystemState::Emergency);
  EXPECT_EQ(sub.holder(), kSafetyComponentId);
  EXPECT_EQ(sub.holder_authority(), 225);
  client.set_mode(ClientMode::Clear);
  for (int i = 0; i < 3; ++i) (void)cycle(s, net.service, client, sub);
  EXPECT_EQ(s.observe().state, SafState::Operational);
  EXPECT_EQ(sub.state(), SubsystemState::Operational);
  EXPECT_EQ(sub.holder(), 0U);
  EXPECT_NE(service_port, 0);
}

TEST(SAF03_UdpFlood, GarbageFloodIsBoundedRejectedAndFailsSafe) {
  Loopback net;
  SafetyService s{Config{}};
  UdpEndpoint flooder;
  ASSERT_EQ(flooder.open(0), UdpError::None);
  SafetyClientSim client{std::move(net.client)};
  SubsystemSim sub{std::move(net.subsystem)};
  for (int i = 0; i < 2; ++i) (void)cycle(s, net.service, client, sub);
  ASSERT_EQ(s.observe().state, SafState::Operational);

  // 20,000 garbage datagrams of every size class; the kernel keeps what fits its buffer.
  std::uint8_t junk[200];
  for (std::size_t i = 0; i < sizeof junk; ++i) junk[i] = static_cast<std::uint8_t>(i * 37U + 11U);
  for (int i = 0; i < 20000; ++i) {
    (void)flooder.send_to(net.service.port(), junk, static_cast<std::size_t>(1 + (i * 7) % 199));
  }
  int cycles = 0;
  int queries_answered = 0;  // cycles in which the subsystem had granted our request
  bool went_emergency = false;
  std::size_t max_read = 0;
  // Run until the flood has drained and the service is back in OPERATIONAL.
  while (cycles < 20000 / 16 + 100) {
    const std::uint64_t before = s.diagnostics().cycles;
    const CycleStats st = cycle(s, net.service, client, sub);
    ++cycles;
    max_read = std::max(max_read, st.read);
    EXPECT_EQ(s.diagnostics().cycles, before + 1);  // one cycle per call, whatever arrives
    if (s.observe().state == SafState::Emergency) went_emergency = true;
    if (sub.holder() == kSafetyComponentId) ++queries_answered;
    if (went_emergency && s.observe().state == SafState::Operational && st.read < kMaxInboundPerCycle) break;
  }
  EXPECT_LE(max_read, kMaxInboundPerCycle);
  EXPECT_TRUE(went_emergency) << "valid Set Estop messages drowned in the flood must time out";
  // The service kept sending during the flood: its Request Control reached the subsystem
  // (whose answers queue behind the garbage in the service's socket).
  EXPECT_GT(queries_answered, 0);
  std::printf("flood: %d cycles, %llu datagrams rejected, at most %zu read per cycle\n", cycles,
              static_cast<unsigned long long>(s.diagnostics().rejected_total()), max_read);
  EXPECT_EQ(s.observe().state, SafState::Operational);
  EXPECT_GT(s.diagnostics().rejected_total(), 100U);
  EXPECT_GT(s.diagnostics().rejected[static_cast<std::size_t>(DecodeError::Oversized)], 0U);
}

}  // namespace
}  // namespace safestate::saf::test
