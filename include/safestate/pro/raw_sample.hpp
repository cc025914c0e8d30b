// One raw reading of the sensor front end (what ao_monitoring samples, §2): the values,
// the front end's rolling frame counter (a frozen counter means a stuck sensor) and its
// own fault flag (open/short circuit detected by the ADC).
#pragma once

#include <cstdint>

namespace safestate::pro {

struct RawSample {
  std::int16_t temperature_c{0};
  std::uint16_t voltage_dv{0};
  std::uint8_t sequence{0};
  bool fault_flag{false};
};

}  // namespace safestate::pro
