// SPDX-License-Identifier: Apache-2.0
// Issue 30 item 3 (design §14): the deployed service (ServiceHost, real UDP sockets on
// 127.0.0.1) while the real Safety Client holds the E-stop SET, against 28 kinds of attack
// datagram from another socket on the host or from the client's own port (a sender that got
// hold of it): spoofed source, replay, stale sequence, wrong component, bad or missing MAC,
// forged Confirm/Report Control and reports, every malformed shape, outgoing types, a
// datagram to the connected subsystem socket, and a flood of 3,000 datagrams. The subsystem
// stays EMERGENCY in every cycle and every attack is counted under its reason. Built and
// run under ASan/UBSan by `bash bench/saf_fuzz.sh --sanitize-only`.
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "saf_host_rig.hpp"

namespace safestate::saf::test {
namespace {

Encoded with_byte(Encoded e, std::size_t at, std::uint8_t value) {
  e.bytes[at] = value;
  return e;
}

Encoded raw(std::initializer_list<std::uint8_t> bytes) {
  Encoded e{};
  for (std::uint8_t b : bytes) e.bytes[e.size++] = b;
  return e;
}

struct Attack {
  std::string name;
  IntakeReason reason;  // None: not for the intake to count (filtered by the kernel)
  std::function<void(HostRig&)> send;
};

struct Captures {
  Encoded first_clear{};  // sequence 1: older than the replay window by the time it is sent
  Encoded last_clear{};
  Encoded last_set{};
};

std::vector<Attack> attacks(const Captures& cap) {
  const MacKey key = test_key();
  const MacKey wrong_key = test_key(0x11);
  const auto from_client = [](const Encoded& e) {
    return [e](HostRig& r) { r.client->send_raw(r.host->client_port(), e); };
  };
  const auto from_attacker = [](const Encoded& e) { return [e](HostRig& r) { r.send(e); }; };
  const auto next = [](HostRig& r) { return r.host->intake().highest_sequence() + 5; };
  std::vector<Attack> a;
  // Spoofed source: another port on the same host.
  a.push_back(
      {"spoofed port, seed clear", IntakeReason::EstopWrongSource, from_attacker(encode(Message::set_estop(false)))});
  a.push_back({"spoofed port, valid MAC and id, sequence 2^40", IntakeReason::EstopWrongSource,
               from_attacker(encode_set_estop(false, kClientId, 1ULL << 40U, key))});
  a.push_back(
      {"spoofed port, replay of a captured clear", IntakeReason::EstopWrongSource, from_attacker(cap.last_clear)});
  // Freshness: from the client's own port.
  a.push_back({"replay of the last clear", IntakeReason::EstopReplay, from_client(cap.last_clear)});
  a.push_back({"replay of the last set (duplicate)", IntakeReason::EstopReplay, from_client(cap.last_set)});
  a.push_back({"stale clear (sequence 1)", IntakeReason::EstopStale, from_client(cap.first_clear)});
  // Form and authentication.
  a.push_back({"seed form clear from the client port", IntakeReason::EstopUnsequenced,
               from_client(encode(Message::set_estop(false)))});
  a.push_back({"sequenced clear without MAC", IntakeReason::EstopUnauthenticated, [next](HostRig& r) {
                 r.client->send_raw(r.host->client_port(), encode_set_estop(false, kClientId, next(r), MacKey{}));
               }});
  a.push_back({"clear under another key", IntakeReason::EstopBadMac, [next, wrong_key](HostRig& r) {
                 r.client->send_raw(r.host->client_port(), encode_set_estop(false, kClientId, next(r), wrong_key));
               }});
  a.push_back({"captured MAC, sequence raised", IntakeReason::EstopBadMac,
               from_client(with_byte(cap.last_clear, kHeaderSize + 12, 0x7F))});
  a.push_back({"captured set with the emergency bit cleared", IntakeReason::EstopBadMac,
               from_client(with_byte(cap.last_set, kHeaderSize, 0))});
  a.push_back({"valid MAC, another component id", IntakeReason::EstopWrongComponent, [next, key](HostRig& r) {
                 r.client->send_raw(r.host->client_port(), encode_set_estop(false, 0x00DE'AD00, next(r), key));
               }});
  // Forged answers and reports of the subsystem.
  a.push_back({"forged Confirm Control(accepted)", IntakeReason::ReportWrongSource,
               from_attacker(encode(Message::confirm_control(ControlResponse::Accepted)))});
  a.push_back({"forged Report Control(us, authority 0)", IntakeReason::ReportWrongSource,
               from_attacker(encode(Message::report_control(kSafetyComponentId, 0)))});
  a.push_back({"forged Report Control(another holder, 255)", IntakeReason::ReportWrongSource,
               from_attacker(encode(Message::report_control(0x0009'0909, 255)))});
  a.push_back({"forged Report Health Summary(normal)", IntakeReason::ReportWrongSource,
               from_attacker(encode(Message::report_health(Health::Normal)))});
  a.push_back({"forged Report Subsystem State(operational)", IntakeReason::ReportWrongSource,
               from_attacker(encode(Message::report_subsystem_state(SubsystemState::Operational)))});
  a.push_back({"a report from the client's port", IntakeReason::ReportWrongSource,
               from_client(encode(Message::confirm_control(ControlResponse::Accepted)))});
  // Malformed.
  a.push_back({"empty datagram", IntakeReason::Truncated, [](HostRig& r) { r.send(nullptr, 0); }});
  a.push_back({"truncated header", IntakeReason::Truncated, from_attacker(raw({0x3c, 0x01, 0x00, 0x00, 0x01}))});
  Encoded short_payload = cap.last_clear;
  short_payload.size = kHeaderSize + 5;
  a.push_back({"truncated payload", IntakeReason::Truncated, from_attacker(short_payload)});
  a.push_back({"oversized (100 bytes)", IntakeReason::Oversized, [](HostRig& r) {
                 std::vector<std::uint8_t> big(100, 0xEE);
                 r.send(big.data(), big.size());
               }});
  Encoded trailing = encode(Message::set_estop(false));
  trailing.bytes[trailing.size++] = 0;
  a.push_back({"trailing bytes", IntakeReason::TrailingBytes, from_attacker(trailing)});
  a.push_back(
      {"unknown id", IntakeReason::UnknownId, from_attacker(with_byte(encode(Message::set_estop(false)), 0, 0x99))});
  a.push_back({"bad length (Set Estop payload 2)", IntakeReason::BadLength,
               from_attacker(raw({0x3c, 0x01, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00}))});
  a.push_back({"field range (emergency = 2)", IntakeReason::FieldRange,
               from_client(with_byte(cap.last_clear, kHeaderSize, 2))});
  a.push_back({"Set Subsystem State(operational) sent to the service", IntakeReason::NotIncoming,
               from_attacker(encode(Message::set_subsystem_state(SubsystemState::Operational)))});
  a.push_back({"Request Control(release) sent to the service", IntakeReason::NotIncoming,
               from_attacker(encode(Message::request_control(ControlAction::Release, 255, kSafetyComponentId)))});
  // Below the service: the subsystem socket is connected, the kernel delivers nothing else.
  a.push_back({"forged Confirm Control to the subsystem socket", IntakeReason::None, [](HostRig& r) {
                 (void)r.attacker.send_to(r.host->subsystem_port(),
                                          encode(Message::confirm_control(ControlResponse::Accepted)));
               }});
  return a;
}

void expect_emergency(const HostRig& r, const std::string& during) {
  EXPECT_EQ(r.subsystem->state(), SubsystemState::Emergency) << "subsystem, during: " << during;
  EXPECT_EQ(r.host->service().observe().state, SafState::Emergency) << "service, during: " << during;
}

/// The real client clear for 70 cycles (sequence 1 .. 70), then SET until the subsystem is
/// EMERGENCY; the captures for the replays.
Captures press_and_capture(HostRig& r) {
  Captures cap{};
  r.client->set_mode(ClientMode::Clear);
  for (int i = 0; i < 70; ++i) {
    (void)r.cycle();
    if (i == 0) cap.first_clear = r.client->last_sent();
  }
  EXPECT_EQ(r.host->service().observe().state, SafState::Operational);
  cap.last_clear = r.client->last_sent();
  r.client->set_mode(ClientMode::Emergency);
  for (int i = 0; i < 4; ++i) (void)r.cycle();
  cap.last_set = r.client->last_sent();
  expect_emergency(r, "the real press");
  return cap;
}

TEST(SAF03_HostileSender, EveryAttackRejectedAndCountedWhileTheEstopIsSet) {
  HostRig r{true};
  const Captures cap = press_and_capture(r);
  constexpr int kRepeats = 3;
  const std::vector<Attack> all = attacks(cap);
  ASSERT_GE(all.size(), 20U);
  std::printf("%-55s %-24s %s\n", "attack", "counted as", "count");
  for (const Attack& a : all) {
    const IntakeCounters before = r.host->intake().counters();
    for (int i = 0; i < kRepeats; ++i) {
      a.send(r);
      (void)r.cycle();
      expect_emergency(r, a.name);
    }
    const IntakeCounters& after = r.host->intake().counters();
    if (a.reason == IntakeReason::None) {
      EXPECT_EQ(after.rejected_total(), before.rejected_total()) << a.name << ": reached the service";
      std::printf("%-55s %-24s %d (not delivered by the kernel)\n", a.name.c_str(), "-", 0);
      continue;
    }
    EXPECT_EQ(after.of(a.reason) - before.of(a.reason), static_cast<std::uint64_t>(kRepeats)) << a.name;
    EXPECT_EQ(after.rejected_total() - before.rejected_total(), static_cast<std::uint64_t>(kRepeats))
        << a.name << ": counted under another reason too";
    std::printf("%-55s %-24s %llu\n", a.name.c_str(), std::string(to_string(a.reason)).c_str(),
                static_cast<unsigned long long>(after.of(a.reason) - before.of(a.reason)));
  }
  // The flood: 3,000 datagrams (forged clears and garbage) in one burst.
  const std::uint64_t drops_before = r.host->kernel_dropped();
  for (int i = 0; i < 3000; ++i) {
    if (i % 2 == 0) {
      r.send(encode_set_estop(false, kClientId, r.host->intake().highest_sequence() + 1, test_key(0x22)));
    } else {
      r.send(encode(Message::report_control(kSafetyComponentId, 0)));
    }
  }
  int cycles = 0;
  for (; cycles < 400; ++cycles) {
    const HostCycle c = r.cycle();
    expect_emergency(r, "the flood");
    if (c.received < kMaxInboundPerCycle && !c.overflow) break;
  }
  EXPECT_LT(cycles, 400) << "the backlog never drained";
  EXPECT_GT(r.host->kernel_dropped() - drops_before, 0U) << "kernel drops not counted";
  EXPECT_EQ(r.host->service().diagnostics().inbound_dropped, r.host->kernel_dropped());
  EXPECT_GT(r.host->overflow_cycles(), 0U);
  std::printf("%-55s kernel drops %llu, overflow cycles %llu, drained after %d cycles\n", "flood of 3000",
              static_cast<unsigned long long>(r.host->kernel_dropped() - drops_before),
              static_cast<unsigned long long>(r.host->overflow_cycles()), cycles);
  // The real client releases: the service follows it (nothing the attacks did sticks).
  r.client->set_mode(ClientMode::Clear);
  for (int i = 0; i < 30; ++i) (void)r.cycle();
  EXPECT_EQ(r.host->service().observe().state, SafState::Operational);
  EXPECT_EQ(r.subsystem->state(), SubsystemState::Operational);
}

TEST(SAF03_HostileSender, WithoutKeyTheSequenceStillRejectsReplayAndSeedForm) {
  HostRig r{false};
  const Captures cap = press_and_capture(r);
  for (int i = 0; i < 3; ++i) {
    r.client->send_raw(r.host->client_port(), cap.last_clear);
    r.client->send_raw(r.host->client_port(), encode(Message::set_estop(false)));
    r.client->send_raw(r.host->client_port(), encode_set_estop(false, kClientId, 1ULL << 50U, test_key()));
    (void)r.cycle();
    expect_emergency(r, "replay without key");
  }
  const IntakeCounters& c = r.host->intake().counters();
  EXPECT_EQ(c.of(IntakeReason::EstopReplay), 3U);
  EXPECT_EQ(c.of(IntakeReason::EstopUnsequenced), 3U);
  EXPECT_EQ(c.of(IntakeReason::EstopBadMac), 3U);  // a MAC where no key is configured
}

// req: SAF-02
TEST(SAF03_HostileSender, AFloodWhileClearBringsTheSubsystemToEmergency) {
  HostRig r{true};
  r.client->set_mode(ClientMode::Clear);
  for (int i = 0; i < 30; ++i) (void)r.cycle();
  ASSERT_EQ(r.subsystem->state(), SubsystemState::Operational);
  // A sustained flood: 300 datagrams after every cycle; the real client sends once more
  // just before them, so that its clear still gets into the socket, behind the flood. Read in an overflow cycle it is
  // no evidence (it may stand for others the kernel dropped): the E-stop times out, and the delayed clears that come
  // out of the backlog later do not release it.
  int cycles_to_emergency = -1;
  for (int i = 0; i < 40; ++i) {
    (void)r.cycle();
    r.client->step(r.host->client_port());
    for (int j = 0; j < 300; ++j) r.send(encode(Message::set_estop(false)));
    if (r.subsystem->state() == SubsystemState::Emergency && cycles_to_emergency < 0) cycles_to_emergency = i + 1;
    if (cycles_to_emergency > 0) {
      EXPECT_EQ(r.subsystem->state(), SubsystemState::Emergency) << "released during the flood, cycle " << i;
    }
  }
  const Timing t = r.host->service().timing();
  ASSERT_GT(cycles_to_emergency, 0) << "the subsystem stayed OPERATIONAL through the flood";
  // E-stop timeout, then Request Control, Confirm Control and Set Subsystem State.
  EXPECT_LE(cycles_to_emergency, static_cast<int>(t.estop_timeout) + 3);
  EXPECT_GT(r.host->intake().counters().of(IntakeReason::EstopClearInOverflow), 0U);
  std::printf("flood while clear: subsystem EMERGENCY after %d cycles, kernel drops %llu\n", cycles_to_emergency,
              static_cast<unsigned long long>(r.host->kernel_dropped()));
}

}  // namespace
}  // namespace safestate::saf::test
