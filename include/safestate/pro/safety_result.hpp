// ao_safety's result codes (the seed's ao_safety_result, PRO-02).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class SafetyResult : std::uint8_t { ok = 0, protection_entered = 1, latch_blocked = 2 };

}  // namespace safestate::pro
