// The rows P01..P05 of sm_protection (docs/design/protection.md §4), first match wins.
#pragma once

#include <cstdint>

#include "safestate/pro/protection_state.hpp"

namespace safestate::pro {

enum class ProtectionRow : std::uint8_t { p01, p02, p03, p04, p05 };

[[nodiscard]] constexpr ProtectionRow select_row(ProtectionState state, bool hazard,
                                                 bool clear_request) noexcept {
  if (state == ProtectionState::normal) {
    return hazard ? ProtectionRow::p01 : ProtectionRow::p02;
  }
  if (clear_request && hazard) {
    return ProtectionRow::p03;
  }
  return clear_request ? ProtectionRow::p04 : ProtectionRow::p05;
}

}  // namespace safestate::pro
