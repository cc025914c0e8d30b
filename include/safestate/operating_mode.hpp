// SPDX-License-Identifier: Apache-2.0
// Operating mode of a servo-on session (design §4, RSM-02).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "safestate/selector_reading.hpp"

namespace safestate {

/// The operating mode of a powered session (`session_mode`, §4): latched from the selector
/// at the accepted Servo-on; None outside the powered states.
enum class OperatingMode : std::uint8_t {
  None,
  Auto,
  T1,
  T2,
};

inline constexpr std::size_t kOperatingModeCount = 4;

inline constexpr std::array<OperatingMode, kOperatingModeCount> kAllOperatingModes{
    OperatingMode::None,
    OperatingMode::Auto,
    OperatingMode::T1,
    OperatingMode::T2,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(OperatingMode v) noexcept {
  switch (v) {
    case OperatingMode::None: return "NONE";
    case OperatingMode::Auto: return "AUTO";
    case OperatingMode::T1: return "T1";
    case OperatingMode::T2: return "T2";
  }
  return "?";
}

/// T1 or T2: the manual modes (RSM-09). `manual` in the design tables.
[[nodiscard]] constexpr bool is_manual(OperatingMode m) noexcept {
  return m == OperatingMode::T1 || m == OperatingMode::T2;
}

/// The session mode a Servo-on latches from a selector reading (K12); None for Invalid.
[[nodiscard]] constexpr OperatingMode mode_of(SelectorReading r) noexcept {
  switch (r) {
    case SelectorReading::Auto: return OperatingMode::Auto;
    case SelectorReading::T1: return OperatingMode::T1;
    case SelectorReading::T2: return OperatingMode::T2;
    case SelectorReading::Invalid: return OperatingMode::None;
  }
  return OperatingMode::None;
}

/// `selector = session_mode` of C12: an Invalid reading never equals a mode.
[[nodiscard]] constexpr bool selector_matches(SelectorReading r, OperatingMode m) noexcept {
  return r != SelectorReading::Invalid && mode_of(r) == m;
}

}  // namespace safestate
