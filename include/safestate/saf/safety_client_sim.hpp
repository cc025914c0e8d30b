// SPDX-License-Identifier: Apache-2.0
// A simulated Safety Client (the E-stop source): sends Set Estop every cycle, or the
// emergency, or nothing, or garbage (design §9, the demo and the robustness tests). Its
// Set Estop is the extension's (design §14): its component id, a sequence number that
// rises by one per message, and the MAC when a key is given.
#pragma once

#include <cstdint>

#include "safestate/saf/estop_extension.hpp"
#include "safestate/saf/udp_endpoint.hpp"

namespace safestate::saf {

enum class ClientMode : std::uint8_t { Clear, Emergency, Silent, Garbage };

class SafetyClientSim {
 public:
  explicit SafetyClientSim(UdpEndpoint endpoint) noexcept : ep_(static_cast<UdpEndpoint&&>(endpoint)) {}
  /// The id, key and first sequence number of the Set Estop it sends.
  void configure(std::uint32_t component_id, const MacKey& key, std::uint64_t first_sequence) noexcept {
    component_id_ = component_id;
    key_ = key;
    sequence_ = first_sequence;
  }
  void set_mode(ClientMode m) noexcept { mode_ = m; }
  [[nodiscard]] ClientMode mode() const noexcept { return mode_; }
  /// One cycle: sends what the mode says to the service's port.
  void step(std::uint16_t service_port) noexcept;
  /// The last Set Estop sent (a capture, for the replay tests).
  [[nodiscard]] const Encoded& last_sent() const noexcept { return last_; }
  [[nodiscard]] std::uint16_t port() const noexcept { return ep_.port(); }
  /// Sends raw bytes from the client's own socket (tests: a replay from the client's port).
  void send_raw(std::uint16_t service_port, const Encoded& e) noexcept { (void)ep_.send_to(service_port, e); }

 private:
  UdpEndpoint ep_;
  ClientMode mode_ = ClientMode::Clear;
  std::uint32_t garbage_seed_ = 1;
  std::uint32_t component_id_ = 0;
  MacKey key_{};
  std::uint64_t sequence_ = 1;
  Encoded last_{};
};

}  // namespace safestate::saf
