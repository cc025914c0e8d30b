// SPDX-License-Identifier: Apache-2.0
// A simulated subsystem: the Subsystem State service with its access control, and the
// health summary the service queries (design §7, §9).
#pragma once

#include <cstdint>

#include "safestate/saf/udp_endpoint.hpp"

namespace safestate::saf {

class SubsystemSim {
 public:
  explicit SubsystemSim(UdpEndpoint endpoint) noexcept : ep_(static_cast<UdpEndpoint&&>(endpoint)) {}

  /// Handles every waiting message (Request Control, Query Control, Set Subsystem State,
  /// Query Health Summary) and answers the sender. Returns the number handled.
  std::size_t step() noexcept;

  /// Another component takes control (e.g. a teleoperator of higher authority): control is
  /// granted to it if its authority is at least the holder's; the holder is told.
  void take_control(std::uint32_t component, std::uint8_t authority) noexcept;
  void release_other() noexcept;
  void set_health(Health h) noexcept { health_ = h; }

  [[nodiscard]] std::uint16_t port() const noexcept { return ep_.port(); }
  [[nodiscard]] SubsystemState state() const noexcept { return state_; }
  [[nodiscard]] std::uint32_t holder() const noexcept { return holder_; }
  [[nodiscard]] std::uint8_t holder_authority() const noexcept { return holder_authority_; }

 private:
  void handle(const Message& m, std::uint16_t from) noexcept;
  void report_control(std::uint16_t to) noexcept;

  UdpEndpoint ep_;
  SubsystemState state_ = SubsystemState::Operational;
  Health health_ = Health::Normal;
  std::uint32_t holder_ = 0;  // 0: nobody
  std::uint8_t holder_authority_ = 0;
  std::uint16_t holder_port_ = 0;
};

}  // namespace safestate::saf
