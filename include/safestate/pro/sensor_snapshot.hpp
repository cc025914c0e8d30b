// One validated sensor snapshot of a tick (docs/design/protection.md §2).
#pragma once

#include <cstdint>

namespace safestate::pro {

struct SensorSnapshot {
  std::int16_t temperature_c{0};
  std::uint16_t voltage_dv{0};  // decivolts: the thresholds compare exactly
  bool sensor_valid{false};     // zero-initialised = invalid = protective
  bool clear_request{false};
  // The seed's ao_safety_event.hazard_detected: a hazard another part of the controller
  // detected (the fan driver's fault line: the cooling device is lost), §2.
  bool hazard_detected{false};
};

}  // namespace safestate::pro
