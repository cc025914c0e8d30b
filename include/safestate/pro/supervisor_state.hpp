// The runtime supervisor's states (docs/design/protection.md §6); the values are those of
// ProcessImage::supervisor_state (Modbus input register 4).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class SupervisorState : std::uint8_t { init = 0, run, degraded, shutting_down, stopped };

}  // namespace safestate::pro
