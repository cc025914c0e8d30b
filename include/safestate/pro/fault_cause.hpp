// The fault event ao_safety publishes to diagnostics (docs/design/protection.md §3, §4).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class FaultCause : std::uint8_t {
  none = 0,
  sensor_invalid,
  over_temperature,
  under_voltage,
  over_voltage,
  latch_blocked,
  hazard_detected,  // the event's hazard_detected flag (the fan driver's fault line, §2)
};

}  // namespace safestate::pro
