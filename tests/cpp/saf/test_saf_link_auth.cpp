// SPDX-License-Identifier: Apache-2.0
// Issue 30, the authenticated service <-> subsystem link (design §15): the sealed form of
// every link message, its verdicts (seed form, wrong key, wrong direction, a flipped byte,
// replay, stale), and the deployed service and the subsystem simulator against a process
// that took over the other end's port while that end was dead. Without a key the link is
// the seed's, as before (the last two tests show what the key closes).
#include <gtest/gtest.h>

#include "saf_host_rig.hpp"
#include "safestate/saf/link_auth.hpp"

namespace safestate::saf::test {
namespace {

bool same_bytes(const Datagram& d, const Encoded& e) {
  if (d.size != e.size) return false;
  for (std::size_t i = 0; i < e.size; ++i) {
    if (d.bytes[i] != e.bytes[i]) return false;
  }
  return true;
}

LinkVerdict open_verdict(const Encoded& e, LinkDirection dir, const MacKey& key, LinkReceiver& rx) {
  Datagram out{};
  return link_open(e.bytes.data(), e.size, dir, key, rx, out).verdict;
}

TEST(SAF_LinkAuth, EveryLinkMessageSealsAndOpensToItsSeedForm) {
  const MacKey key = test_key();
  const Message messages[] = {
      Message::report_health(Health::Normal),
      Message::confirm_control(ControlResponse::Accepted),
      Message::report_control(0x0001'0203, 225),
      Message::report_subsystem_state(SubsystemState::Operational),
      Message::request_control(ControlAction::Request, 225, 0x0001'0203),
      Message::set_subsystem_state(SubsystemState::Emergency),
  };
  LinkReceiver rx{};
  std::uint64_t seq = 10;
  for (const Message& m : messages) {
    const Encoded seed = encode(m);
    const Encoded sealed = link_seal(seed, seq, LinkDirection::SubsystemToService, key);
    ASSERT_EQ(sealed.size, seed.size + kLinkTrailer);
    EXPECT_EQ(sealed.bytes[8] | (sealed.bytes[9] << 8U), seed.size - kHeaderSize + kLinkTrailer);
    Datagram out{};
    const LinkOpened o = link_open(sealed.bytes.data(), sealed.size, LinkDirection::SubsystemToService, key, rx, out);
    EXPECT_EQ(o.verdict, LinkVerdict::Ok);
    EXPECT_EQ(o.sequence, seq);
    EXPECT_TRUE(same_bytes(out, seed));
    EXPECT_TRUE(decode(out.bytes.data(), out.size).ok());
    ++seq;
  }
  // No key: the seed's form, unchanged.
  const Encoded seed = encode(Message::report_health(Health::Error));
  EXPECT_EQ(link_seal(seed, 1, LinkDirection::SubsystemToService, MacKey{}).size, seed.size);
}

TEST(SAF_LinkAuth, ForgedReflectedReplayedAndStaleLinkMessagesAreRejected) {
  const MacKey key = test_key();
  const Encoded seed = encode(Message::report_health(Health::Normal));
  LinkReceiver rx{};
  rx.window = 8;
  EXPECT_EQ(open_verdict(seed, LinkDirection::SubsystemToService, key, rx), LinkVerdict::Unauthenticated);
  EXPECT_EQ(open_verdict(link_seal(seed, 100, LinkDirection::SubsystemToService, test_key(0x11)),
                         LinkDirection::SubsystemToService, key, rx),
            LinkVerdict::BadMac);
  // The same key in the other direction (a reflected message) does not verify.
  EXPECT_EQ(open_verdict(link_seal(seed, 100, LinkDirection::ServiceToSubsystem, key),
                         LinkDirection::SubsystemToService, key, rx),
            LinkVerdict::BadMac);
  Encoded flipped = link_seal(seed, 100, LinkDirection::SubsystemToService, key);
  flipped.bytes[kHeaderSize] ^= 0x02U;  // NORMAL -> ERROR under the old MAC
  EXPECT_EQ(open_verdict(flipped, LinkDirection::SubsystemToService, key, rx), LinkVerdict::BadMac);
  EXPECT_FALSE(rx.have);  // nothing above advanced the window
  const Encoded good = link_seal(seed, 100, LinkDirection::SubsystemToService, key);
  EXPECT_EQ(open_verdict(good, LinkDirection::SubsystemToService, key, rx), LinkVerdict::Ok);
  EXPECT_EQ(open_verdict(good, LinkDirection::SubsystemToService, key, rx), LinkVerdict::Replay);
  EXPECT_EQ(open_verdict(link_seal(seed, 93, LinkDirection::SubsystemToService, key), LinkDirection::SubsystemToService,
                         key, rx),
            LinkVerdict::Replay);  // 100 - 93 = 7 < 8
  EXPECT_EQ(open_verdict(link_seal(seed, 92, LinkDirection::SubsystemToService, key), LinkDirection::SubsystemToService,
                         key, rx),
            LinkVerdict::Stale);
  EXPECT_EQ(rx.highest, 100U);
  Encoded truncated = good;
  truncated.size -= 1;
  EXPECT_EQ(open_verdict(truncated, LinkDirection::SubsystemToService, key, rx), LinkVerdict::Unauthenticated);
}

/// Runs the rig until the subsystem is held EMERGENCY by the service (client SET).
void press(HostRig& r) {
  r.client->set_mode(ClientMode::Emergency);
  for (int i = 0; i < 20; ++i) r.cycle();
  ASSERT_EQ(r.subsystem->state(), SubsystemState::Emergency);
  ASSERT_EQ(r.subsystem->holder(), kSafetyComponentId);
}

/// The service has died; a process binds its subsystem port and sends the subsystem a
/// Set Subsystem State(OPERATIONAL) (the seed's form, under another key, a stale sealed
/// one) every cycle. Returns the subsystem's state after 20 such cycles.
SubsystemState impersonate_service(HostRig& r) {
  const std::uint16_t service_port = r.host->subsystem_port();
  r.host.reset();
  UdpEndpoint impostor;
  EXPECT_EQ(impostor.open(service_port), UdpError::None);
  const Encoded release = encode(Message::set_subsystem_state(SubsystemState::Operational));
  for (int i = 0; i < 20; ++i) {
    (void)impostor.send_to(r.subsystem->port(), release);
    (void)impostor.send_to(r.subsystem->port(),
                           link_seal(release, 1ULL << 62U, LinkDirection::ServiceToSubsystem, test_key(0x33)));
    (void)impostor.send_to(r.subsystem->port(), link_seal(release, 1, LinkDirection::ServiceToSubsystem, test_key()));
    r.subsystem->step();
    EXPECT_EQ(r.subsystem->state(), SubsystemState::Emergency) << "cycle " << i;
  }
  return r.subsystem->state();
}

TEST(SAF_LinkAuth, AProcessOnTheDeadServicesPortDoesNotReleaseTheSubsystem) {
  HostRig r(true);
  press(r);
  EXPECT_EQ(impersonate_service(r), SubsystemState::Emergency);
  EXPECT_EQ(r.subsystem->rejected(LinkVerdict::Unauthenticated), 20U);
  EXPECT_EQ(r.subsystem->rejected(LinkVerdict::BadMac), 20U);
  EXPECT_EQ(r.subsystem->rejected(LinkVerdict::Replay) + r.subsystem->rejected(LinkVerdict::Stale), 20U);
}

/// The subsystem has died after reporting a health ERROR; a process binds its port and
/// sends the service Report Health(NORMAL) and Confirm Control(ACCEPTED) every cycle
/// while the client sends CLEAR. Returns how many cycles the service was OPERATIONAL.
int impersonate_subsystem(HostRig& r) {
  r.subsystem->set_health(Health::Error);
  r.client->set_mode(ClientMode::Clear);
  for (int i = 0; i < 30; ++i) r.cycle();
  EXPECT_EQ(r.host->service().observe().state, SafState::Emergency);
  const std::uint16_t subsystem_port = r.subsystem->port();
  r.subsystem.reset();
  UdpEndpoint impostor;
  EXPECT_EQ(impostor.open(subsystem_port), UdpError::None);
  const Encoded normal = encode(Message::report_health(Health::Normal));
  const Encoded accepted = encode(Message::confirm_control(ControlResponse::Accepted));
  int operational = 0;
  for (int i = 0; i < 40; ++i) {
    (void)impostor.send_to(r.host->subsystem_port(), normal);
    (void)impostor.send_to(r.host->subsystem_port(), accepted);
    (void)impostor.send_to(r.host->subsystem_port(),
                           link_seal(normal, 1ULL << 62U, LinkDirection::SubsystemToService, test_key(0x33)));
    r.client->step(r.host->client_port());
    r.host->step(false);
    if (r.host->service().observe().state == SafState::Operational) ++operational;
  }
  return operational;
}

TEST(SAF_LinkAuth, ForgedHealthAndConfirmControlFromTheSubsystemsPortAreRejectedAndCounted) {
  HostRig r(true);
  EXPECT_EQ(impersonate_subsystem(r), 0);
  const IntakeCounters& c = r.host->intake().counters();
  EXPECT_EQ(c.of(IntakeReason::ReportUnauthenticated), 80U);  // 40 health, 40 confirm
  EXPECT_EQ(c.of(IntakeReason::ReportBadMac), 40U);
}

TEST(SAF_LinkAuth, WithoutAKeyTheLinkIsTheSeedsAndAnImpostorSucceeds) {
  // The deployment without key works as before the extension -- and this is what it
  // leaves open (design §15): the key is what closes it.
  HostRig service_dies(false);
  press(service_dies);
  const std::uint16_t service_port = service_dies.host->subsystem_port();
  service_dies.host.reset();
  UdpEndpoint impostor;
  ASSERT_EQ(impostor.open(service_port), UdpError::None);
  (void)impostor.send_to(service_dies.subsystem->port(),
                         encode(Message::set_subsystem_state(SubsystemState::Operational)));
  service_dies.subsystem->step();
  EXPECT_EQ(service_dies.subsystem->state(), SubsystemState::Operational);

  HostRig subsystem_dies(false);
  EXPECT_GT(impersonate_subsystem(subsystem_dies), 0);
}

}  // namespace
}  // namespace safestate::saf::test
