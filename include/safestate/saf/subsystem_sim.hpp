// SPDX-License-Identifier: Apache-2.0
// A simulated subsystem: the Subsystem State service with its access control, and the
// health summary the service queries (design §7, §9). With a key (design §15) it accepts
// only the service's sealed, fresh messages and seals its answers.
#pragma once

#include <array>
#include <cstdint>

#include "safestate/saf/link_auth.hpp"
#include "safestate/saf/udp_endpoint.hpp"

namespace safestate::saf {

class SubsystemSim {
 public:
  explicit SubsystemSim(UdpEndpoint endpoint) noexcept : ep_(static_cast<UdpEndpoint&&>(endpoint)) {}

  /// The link key (design §15): with one present, a datagram that is not sealed by the
  /// service, or not fresh, is rejected and counted (`rejected(v)`), and every answer is
  /// sealed with a sequence starting at `first_sequence`.
  void configure_link(const MacKey& key, std::uint64_t first_sequence, std::uint64_t window = 64) noexcept {
    key_ = key;
    next_sequence_ = first_sequence;
    rx_.window = window;
  }
  [[nodiscard]] std::uint64_t rejected(LinkVerdict v) const noexcept { return rejected_[static_cast<std::size_t>(v)]; }

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
  void send(std::uint16_t to, const Message& m) noexcept;

  UdpEndpoint ep_;
  SubsystemState state_ = SubsystemState::Operational;
  Health health_ = Health::Normal;
  std::uint32_t holder_ = 0;  // 0: nobody
  std::uint8_t holder_authority_ = 0;
  std::uint16_t holder_port_ = 0;
  MacKey key_{};
  LinkReceiver rx_{};
  std::uint64_t next_sequence_ = 1;
  std::array<std::uint64_t, 5> rejected_{};  // indexed by LinkVerdict
};

}  // namespace safestate::saf
