#include "safestate/pro/ao_safety.hpp"

namespace safestate::pro {

FaultCause AoSafety::hazard_cause(const SensorSnapshot& s) const noexcept {
  if (!s.sensor_valid) return FaultCause::sensor_invalid;
  if (s.temperature_c > limits_.temp_limit_c) return FaultCause::over_temperature;
  if (s.voltage_dv < limits_.volt_min_dv) return FaultCause::under_voltage;
  if (s.voltage_dv > limits_.volt_max_dv) return FaultCause::over_voltage;
  if (s.hazard_detected) return FaultCause::hazard_detected;
  return FaultCause::none;
}

SafetyResult AoSafety::dispatch(const SensorSnapshot& s, std::uint32_t tick) noexcept {
  const FaultCause cause = hazard_cause(s);
  const bool hazard = cause != FaultCause::none;
  last_row_ = select_row(ctx_.protection_state, hazard, s.clear_request, degraded_);
  last_fault_ = FaultCause::none;
  switch (last_row_) {
    case ProtectionRow::p01:
      ctx_ = SafetyContext{ProtectionState::protection, true, true, tick};
      last_fault_ = cause;
      return SafetyResult::protection_entered;
    case ProtectionRow::p03: last_fault_ = FaultCause::latch_blocked; return SafetyResult::latch_blocked;
    case ProtectionRow::p04: ctx_ = SafetyContext{ProtectionState::normal, false, false, tick}; return SafetyResult::ok;
    case ProtectionRow::p02:
    case ProtectionRow::p05: break;
  }
  return SafetyResult::ok;
}

}  // namespace safestate::pro
