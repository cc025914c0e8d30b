// The rows P01..P05 of sm_protection (docs/design/protection.md §4) as constexpr data,
// first match wins among the rows of a state; the row IDs are the design page's.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "safestate/pro/protection_state.hpp"

namespace safestate::pro {

enum class ProtectionRow : std::uint8_t { p01, p02, p03, p04, p05 };

// A row's guard over the tick's hazard (hz), clear request (clr) and ao_safety's degraded
// mode (dg, §4a: the latch guard of a clear is "no hazard and not degraded").
enum class ProtectionGuard : std::uint8_t {
  hazard,             // hz
  clear_and_blocked,  // clr ∧ (hz ∨ dg)
  clear_and_free,     // clr ∧ ¬hz ∧ ¬dg
  always,             // TRUE
};

struct ProtectionRowSpec {
  std::string_view id;
  ProtectionRow row;
  ProtectionState state;
  ProtectionGuard guard;
};

inline constexpr std::array<ProtectionRowSpec, 5> kProtectionRows{{
    {"P01", ProtectionRow::p01, ProtectionState::normal, ProtectionGuard::hazard},
    {"P02", ProtectionRow::p02, ProtectionState::normal, ProtectionGuard::always},
    {"P03", ProtectionRow::p03, ProtectionState::protection, ProtectionGuard::clear_and_blocked},
    {"P04", ProtectionRow::p04, ProtectionState::protection, ProtectionGuard::clear_and_free},
    {"P05", ProtectionRow::p05, ProtectionState::protection, ProtectionGuard::always},
}};

[[nodiscard]] constexpr bool guard_holds(ProtectionGuard g, bool hazard, bool clear_request, bool degraded) noexcept {
  switch (g) {
    case ProtectionGuard::hazard: return hazard;
    case ProtectionGuard::clear_and_blocked: return clear_request && (hazard || degraded);
    case ProtectionGuard::clear_and_free: return clear_request && !hazard && !degraded;
    case ProtectionGuard::always: return true;
  }
  return false;
}

// The first row of `state` whose guard holds; every state ends with an `always` row.
[[nodiscard]] constexpr ProtectionRow select_row(ProtectionState state, bool hazard, bool clear_request,
                                                 bool degraded) noexcept {
  for (const ProtectionRowSpec& r : kProtectionRows) {
    if (r.state == state && guard_holds(r.guard, hazard, clear_request, degraded)) {
      return r.row;
    }
  }
  return ProtectionRow::p05;  // unreachable: both states end with an `always` row
}

[[nodiscard]] constexpr std::string_view row_id(ProtectionRow row) noexcept {
  return kProtectionRows[static_cast<std::size_t>(row)].id;
}

// The table's order is the enum's: row_id indexes by it.
static_assert(kProtectionRows[0].row == ProtectionRow::p01 && kProtectionRows[1].row == ProtectionRow::p02 &&
              kProtectionRows[2].row == ProtectionRow::p03 && kProtectionRows[3].row == ProtectionRow::p04 &&
              kProtectionRows[4].row == ProtectionRow::p05);
static_assert(select_row(ProtectionState::normal, true, true, false) == ProtectionRow::p01);
static_assert(select_row(ProtectionState::normal, false, true, true) == ProtectionRow::p02);
static_assert(select_row(ProtectionState::protection, true, true, false) == ProtectionRow::p03);
static_assert(select_row(ProtectionState::protection, false, true, true) == ProtectionRow::p03);
static_assert(select_row(ProtectionState::protection, false, true, false) == ProtectionRow::p04);
static_assert(select_row(ProtectionState::protection, true, false, false) == ProtectionRow::p05);

}  // namespace safestate::pro
