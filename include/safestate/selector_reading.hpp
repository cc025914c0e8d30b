// SPDX-License-Identifier: Apache-2.0
// Mode selector reading (design §2, RSM-02).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// What the hardware mode selector reads: exactly one contact closed gives its mode, none or
/// several give Invalid (RSM-02). Invalid is the value before the first cycle.
enum class SelectorReading : std::uint8_t {
  Invalid,
  Auto,
  T1,
  T2,
};

inline constexpr std::size_t kSelectorReadingCount = 4;

inline constexpr std::array<SelectorReading, kSelectorReadingCount> kAllSelectorReadings{
    SelectorReading::Invalid,
    SelectorReading::Auto,
    SelectorReading::T1,
    SelectorReading::T2,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(SelectorReading v) noexcept {
  switch (v) {
    case SelectorReading::Invalid: return "INVALID";
    case SelectorReading::Auto: return "AUTO";
    case SelectorReading::T1: return "T1";
    case SelectorReading::T2: return "T2";
  }
  return "?";
}

}  // namespace safestate
