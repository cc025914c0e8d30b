// SPDX-License-Identifier: Apache-2.0
// The deployed Safety service (design §14): two UDP sockets (one the Safety Client sends
// to, one connected to the subsystem), the intake in front of the core, and one call per
// scan cycle. The process around it (timing, configuration file, log, signals) is
// `safestate saf serve` (python/safestate/saf_service/).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "safestate/saf/intake.hpp"
#include "safestate/saf/safety_service.hpp"
#include "safestate/saf/udp_endpoint.hpp"

namespace safestate::saf {

struct HostConfig {
  Config parameters{};                              // SAF-04
  std::uint32_t component_id = kSafetyComponentId;  // ours, in Request Control
  std::uint32_t address = kLoopback;                // the address both sockets bind
  std::uint16_t client_port = 0;                    // where the Safety Client sends (0: any)
  std::uint16_t subsystem_port = 0;                 // our socket towards the subsystem (0: any)
  IntakeConfig intake{};                            // the client's and the subsystem's address
  // With a key: the first sequence of our sealed messages to the subsystem (design §15; the
  // process passes the wall clock in microseconds, a restore can only raise it).
  std::uint64_t link_sequence_start = 1;
};

enum class HostError : std::uint8_t { None, ClientSocket, SubsystemSocket, Connect };

[[nodiscard]] constexpr std::string_view to_string(HostError e) noexcept {
  switch (e) {
    case HostError::None: return "none";
    case HostError::ClientSocket: return "cannot bind the Safety Client port";
    case HostError::SubsystemSocket: return "cannot bind the subsystem port";
    case HostError::Connect: return "cannot connect the subsystem socket";
  }
  return "?";
}

/// What one cycle of the host did, for the log.
struct HostCycle {
  SafState before = SafState::Pairing;
  SafState after = SafState::Pairing;
  std::string_view state_row;
  std::string_view control_row;
  IntakeCycle intake{};
  std::size_t received = 0;
  bool overflow = false;             // the client socket dropped datagrams or has a backlog
  std::uint64_t kernel_dropped = 0;  // datagrams the kernel dropped, learnt in this cycle
  Outbox sent{};
};

class ServiceHost {
 public:
  explicit ServiceHost(const HostConfig& config) noexcept;
  /// Binds both sockets and connects the subsystem one. On failure nothing is open and
  /// `last_errno()` tells why.
  [[nodiscard]] HostError open() noexcept;
  /// One scan cycle: read (subsystem socket first, then the client socket, at most
  /// kMaxInboundPerCycle in all), intake, core, send the outbox to the subsystem (sealed
  /// with a key, §15).
  HostCycle step(bool hardware_fault = false) noexcept;

  [[nodiscard]] const SafetyService& service() const noexcept { return service_; }
  [[nodiscard]] const Intake& intake() const noexcept { return intake_; }
  [[nodiscard]] std::uint16_t client_port() const noexcept { return client_.port(); }
  [[nodiscard]] std::uint16_t subsystem_port() const noexcept { return subsystem_.port(); }
  [[nodiscard]] std::uint64_t kernel_dropped() const noexcept { return client_.kernel_dropped(); }
  [[nodiscard]] std::uint64_t overflow_cycles() const noexcept { return overflow_cycles_; }
  [[nodiscard]] std::uint64_t send_dropped() const noexcept { return subsystem_.send_dropped(); }
  [[nodiscard]] int last_errno() const noexcept { return errno_; }

  /// The replay state for the sequence file (design §15): the intake's highest accepted
  /// sequences and the next sequence of our sealed messages.
  [[nodiscard]] SequenceState sequences() const noexcept;
  /// Restores a sequence file's state before the first cycle; our own next sequence only
  /// rises (the larger of the stored one and link_sequence_start).
  void restore(const SequenceState& s) noexcept;

 private:
  HostConfig config_;
  SafetyService service_;
  Intake intake_;
  UdpEndpoint client_;
  UdpEndpoint subsystem_;
  InboundBatch received_{};
  InboundBatch accepted_{};
  std::uint64_t overflow_cycles_ = 0;
  std::uint64_t link_next_ = 1;
  int errno_ = 0;
};

/// The subsystem socket reads at most this many per cycle, the client socket the rest.
inline constexpr std::size_t kSubsystemReadsPerCycle = kMaxInboundPerCycle / 2;

}  // namespace safestate::saf
