// The outcome of the last latch clear request the controller consumed; the values are
// those of ProcessImage::last_clear_result (Modbus input register 5).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class ClearOutcome : std::uint8_t { none = 0, accepted, denied, refused };

}  // namespace safestate::pro
