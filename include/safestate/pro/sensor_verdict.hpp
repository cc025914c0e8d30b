// Why the sensor validator accepted or rejected a raw sample (§2): any reason but `ok`
// makes the snapshot invalid, which is a hazard (PRO-01).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class SensorVerdict : std::uint8_t { ok = 0, flagged, out_of_range, implausible_slew, stuck };

}  // namespace safestate::pro
