// The supervisor's transition table, rows X01..S02 of docs/design/protection.md §7 (and
// T01: STOPPED stays), as constexpr data; first match wins among the rows of a state.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "safestate/pro/supervisor_guard.hpp"
#include "safestate/pro/supervisor_state.hpp"

namespace safestate::pro {

[[nodiscard]] constexpr std::uint8_t state_bit(SupervisorState s) noexcept {
  return static_cast<std::uint8_t>(1U << static_cast<std::uint8_t>(s));
}

struct SupervisorRow {
  std::string_view id;
  std::uint8_t from;  // bit set of source states (state_bit)
  SupervisorGuard guard;
  SupervisorState target;
  bool stay;  // the row keeps the state (target unused)
};

namespace detail {
inline constexpr std::uint8_t kLive =
    state_bit(SupervisorState::init) | state_bit(SupervisorState::run) | state_bit(SupervisorState::degraded);
}  // namespace detail

inline constexpr std::array<SupervisorRow, 12> kSupervisorRows{{
    {"X01", detail::kLive, SupervisorGuard::shutdown_requested, SupervisorState::shutting_down, false},
    {"I01", state_bit(SupervisorState::init), SupervisorGuard::recovery_ok, SupervisorState::run, false},
    {"I02", state_bit(SupervisorState::init), SupervisorGuard::fault, SupervisorState::degraded, false},
    {"I03", state_bit(SupervisorState::init), SupervisorGuard::init_timeout, SupervisorState::degraded, false},
    {"I04", state_bit(SupervisorState::init), SupervisorGuard::always, SupervisorState::init, true},
    {"R01", state_bit(SupervisorState::run), SupervisorGuard::fault, SupervisorState::degraded, false},
    {"R02", state_bit(SupervisorState::run), SupervisorGuard::always, SupervisorState::run, true},
    {"D01", state_bit(SupervisorState::degraded), SupervisorGuard::recovery_ok, SupervisorState::run, false},
    {"D02", state_bit(SupervisorState::degraded), SupervisorGuard::always, SupervisorState::degraded, true},
    {"S01", state_bit(SupervisorState::shutting_down), SupervisorGuard::all_stopped, SupervisorState::stopped, false},
    {"S02", state_bit(SupervisorState::shutting_down), SupervisorGuard::always, SupervisorState::shutting_down, true},
    {"T01", state_bit(SupervisorState::stopped), SupervisorGuard::always, SupervisorState::stopped, true},
}};

}  // namespace safestate::pro
