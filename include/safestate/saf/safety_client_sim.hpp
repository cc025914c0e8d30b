// SPDX-License-Identifier: Apache-2.0
// A simulated Safety Client (the E-stop source): sends Set Estop every cycle, or the
// emergency, or nothing, or garbage (design §9, the demo and the robustness tests).
#pragma once

#include <cstdint>

#include "safestate/saf/udp_endpoint.hpp"

namespace safestate::saf {

enum class ClientMode : std::uint8_t { Clear, Emergency, Silent, Garbage };

class SafetyClientSim {
 public:
  explicit SafetyClientSim(UdpEndpoint endpoint) noexcept : ep_(static_cast<UdpEndpoint&&>(endpoint)) {}
  void set_mode(ClientMode m) noexcept { mode_ = m; }
  [[nodiscard]] ClientMode mode() const noexcept { return mode_; }
  /// One cycle: sends what the mode says to the service's port.
  void step(std::uint16_t service_port) noexcept;

 private:
  UdpEndpoint ep_;
  ClientMode mode_ = ClientMode::Clear;
  std::uint32_t garbage_seed_ = 1;
};

}  // namespace safestate::saf
