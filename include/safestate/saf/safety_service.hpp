// SPDX-License-Identifier: Apache-2.0
// The Safety service (SAF-01..04): a table-driven scan-cycle state machine, independent of
// the transport. Behaviour: docs/design/safety-service.md.
#pragma once

#include <cstdint>

#include "safestate/saf/config.hpp"
#include "safestate/saf/cycle_result.hpp"
#include "safestate/saf/diagnostics.hpp"
#include "safestate/saf/inbound_batch.hpp"
#include "safestate/saf/observable.hpp"
#include "safestate/saf/transition_table.hpp"

namespace safestate::saf {

/// The component id the service puts in Request Control and expects in Report Control.
inline constexpr std::uint32_t kSafetyComponentId = 0x0001'0203;

class SafetyService {
 public:
  /// From the SAF-04 parameters. An invalid Config (validate() != None) constructs the
  /// service in FAULT: it still raises EMERGENCY (design §3).
  explicit SafetyService(const Config& config, std::uint32_t component_id = kSafetyComponentId) noexcept;
  /// From timers already in cycles (the model's constants; the conformance harness). A timer
  /// of 0 or above kMaxTimerCycles constructs the service in FAULT, as an invalid Config.
  SafetyService(const Timing& timing, std::uint8_t authority_code,
                std::uint32_t component_id = kSafetyComponentId) noexcept;

  /// One scan cycle (design §2): intake of `inbound`, state rows, control rows, periodic
  /// queries. No heap, no exceptions; bounded work (at most kMaxInboundPerCycle decodes).
  [[nodiscard]] CycleResult cycle(const InboundBatch& inbound, bool hardware_fault) noexcept;

  [[nodiscard]] const Observable& observe() const noexcept { return obs_; }
  [[nodiscard]] const Diagnostics& diagnostics() const noexcept { return diag_; }
  [[nodiscard]] const Timing& timing() const noexcept { return timing_; }
  [[nodiscard]] ConfigError config_error() const noexcept { return config_error_; }
  [[nodiscard]] std::uint8_t authority_code() const noexcept { return authority_; }
  [[nodiscard]] std::uint32_t component_id() const noexcept { return component_id_; }
  /// Counts datagrams the transport could not fit into a batch (design §9).
  void count_inbound_dropped(std::uint64_t n) noexcept { diag_.inbound_dropped += n; }

  // Derived conditions of design §4 on the current observable state.
  [[nodiscard]] bool estop_timed_out() const noexcept;
  [[nodiscard]] bool health_bad() const noexcept;
  [[nodiscard]] bool danger() const noexcept;
  /// A health summary has been received, is Normal or Warning and is not stale ("no report
  /// yet" is unknown, not healthy: design §4).
  [[nodiscard]] bool health_known_good() const noexcept;

 private:
  struct Intake {
    ControlEvent event = ControlEvent::None;
    bool subsystem_not_emergency = false;  // an accepted Report Subsystem State other than EMERGENCY
  };
  Intake intake(const InboundBatch& inbound) noexcept;
  void resend_step(bool subsystem_not_emergency) noexcept;
  [[nodiscard]] bool state_guard(StateGuard g, bool hardware_fault) const noexcept;
  [[nodiscard]] bool control_guard(ControlGuard g, ControlEvent ev) const noexcept;
  void apply(StateEffect e) noexcept;
  void apply(ControlEffect e) noexcept;
  void add(Outbox& out, const Message& m) const noexcept;

  Timing timing_;
  std::uint8_t authority_;
  std::uint32_t component_id_;
  ConfigError config_error_ = ConfigError::None;
  Observable obs_{};
  Diagnostics diag_{};
};

}  // namespace safestate::saf
