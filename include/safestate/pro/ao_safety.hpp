// ao_safety with its embedded sm_protection (PRO-01..04, docs/design/protection.md §3-§5).
// No heap, no exceptions: dispatch() is one run-to-completion step per tick.
#pragma once

#include <cstdint>

#include "safestate/pro/fault_cause.hpp"
#include "safestate/pro/protection_limits.hpp"
#include "safestate/pro/protection_row.hpp"
#include "safestate/pro/safety_context.hpp"
#include "safestate/pro/safety_result.hpp"
#include "safestate/pro/sensor_snapshot.hpp"

namespace safestate::pro {

// The fan command while protection is active: full cooling (§4, the safe value). Together
// with the equipment permissive off it is the protective output state, outputs_disabled.
inline constexpr std::uint8_t kSafeFanCommandPercent = 100;

class AoSafety {
 public:
  explicit AoSafety(ProtectionLimits limits = {}) noexcept : limits_(limits) {}

  // The first true condition in the order of §3 (none if the snapshot is not hazardous).
  [[nodiscard]] FaultCause hazard_cause(const SensorSnapshot& s) const noexcept;

  // Evaluates one snapshot at `tick`: rows P01..P05.
  [[nodiscard]] SafetyResult dispatch(const SensorSnapshot& s, std::uint32_t tick) noexcept;

  // The output gate: the fan command written to the driver this tick.
  [[nodiscard]] std::uint8_t fan_output(std::uint8_t control_command) const noexcept {
    return ctx_.override_active ? kSafeFanCommandPercent : control_command;
  }
  // The equipment permissive (§4): removed while the override is active, never by
  // regulation; with the safe fan command it is outputs_disabled.
  [[nodiscard]] bool load_enable() const noexcept { return !ctx_.override_active; }

  // EVT_DEGRADED / EVT_RECOVERY (§4a): in degraded mode a clear request is denied; the
  // recovery ends the degraded mode and leaves the latch as it is.
  void set_degraded(bool degraded) noexcept { degraded_ = degraded; }
  [[nodiscard]] bool degraded() const noexcept { return degraded_; }

  [[nodiscard]] const SafetyContext& context() const noexcept { return ctx_; }
  [[nodiscard]] ProtectionRow last_row() const noexcept { return last_row_; }
  // The fault event published to diagnostics by the last dispatch (none if nothing).
  [[nodiscard]] FaultCause last_fault_event() const noexcept { return last_fault_; }

 private:
  ProtectionLimits limits_;
  SafetyContext ctx_{};
  ProtectionRow last_row_{ProtectionRow::p02};
  FaultCause last_fault_{FaultCause::none};
  bool degraded_{false};
};

}  // namespace safestate::pro
