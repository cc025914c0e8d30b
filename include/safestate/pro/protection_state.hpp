// sm_protection's states (docs/design/protection.md §4).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class ProtectionState : std::uint8_t { normal = 0, protection = 1 };

}  // namespace safestate::pro
