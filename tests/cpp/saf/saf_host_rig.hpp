// SPDX-License-Identifier: Apache-2.0
// A deployed service (ServiceHost) on 127.0.0.1 with the simulated Safety Client and
// subsystem and an attacker's sockets, cycle by cycle (design §14). Shared by the attack
// and the flood tests.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "safestate/saf/safety_client_sim.hpp"
#include "safestate/saf/service_host.hpp"
#include "safestate/saf/subsystem_sim.hpp"

namespace safestate::saf::test {

inline constexpr std::uint32_t kClientId = 0x0001'0300;

inline MacKey test_key(std::uint8_t seed = 0x5A) {
  MacKey k{};
  k.size = 32;
  for (std::size_t i = 0; i < k.size; ++i) k.bytes[i] = static_cast<std::uint8_t>(seed + 7 * i);
  return k;
}

inline UdpEndpoint bound() {
  UdpEndpoint e;
  EXPECT_EQ(e.open(0), UdpError::None);
  return e;
}

struct HostRig {
  std::unique_ptr<SubsystemSim> subsystem;
  std::unique_ptr<SafetyClientSim> client;
  std::unique_ptr<ServiceHost> host;
  UdpEndpoint attacker = bound();
  MacKey key{};

  explicit HostRig(bool with_key) {
    if (with_key) key = test_key();
    UdpEndpoint sub = bound();
    UdpEndpoint cli = bound();
    const std::uint16_t sub_port = sub.port();
    const std::uint16_t cli_port = cli.port();
    subsystem = std::make_unique<SubsystemSim>(std::move(sub));
    client = std::make_unique<SafetyClientSim>(std::move(cli));
    client->configure(kClientId, key, 1);
    subsystem->configure_link(key, 1);
    HostConfig c{};
    c.intake.client = Peer{kLoopback, cli_port};
    c.intake.client_component_id = kClientId;
    c.intake.subsystem = Peer{kLoopback, sub_port};
    c.intake.key = key;
    host = std::make_unique<ServiceHost>(c);
    EXPECT_EQ(host->open(), HostError::None);
  }

  /// One cycle: the client sends, the subsystem answers what is waiting, the service runs,
  /// the subsystem handles what the service sent.
  HostCycle cycle() {
    client->step(host->client_port());
    subsystem->step();
    const HostCycle c = host->step(false);
    subsystem->step();
    return c;
  }

  void send(const Encoded& e) { (void)attacker.send_to(host->client_port(), e); }
  void send(const std::uint8_t* data, std::size_t size) { (void)attacker.send_to(host->client_port(), data, size); }
};

}  // namespace safestate::saf::test
