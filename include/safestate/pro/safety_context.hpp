// ao_safety's runtime context: the seed's ao_safety_context fields (PRO-02).
#pragma once

#include <cstdint>

#include "safestate/pro/protection_state.hpp"

namespace safestate::pro {

struct SafetyContext {
  ProtectionState protection_state{ProtectionState::normal};
  bool latch_active{false};
  bool override_active{false};
  std::uint32_t last_transition_tick{0};
};

}  // namespace safestate::pro
