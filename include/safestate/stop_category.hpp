// SPDX-License-Identifier: Apache-2.0
// Stop category (design §7, RSM-03).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// IEC 60204-1 stop categories (RSM-03). None: no stop since initialisation or since the
/// last accepted Servo-on (K12).
enum class StopCategory : std::uint8_t {
  None,
  Cat0,
  Cat1,
  Cat2,
};

inline constexpr std::size_t kStopCategoryCount = 4;

inline constexpr std::array<StopCategory, kStopCategoryCount> kAllStopCategories{
    StopCategory::None,
    StopCategory::Cat0,
    StopCategory::Cat1,
    StopCategory::Cat2,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(StopCategory v) noexcept {
  switch (v) {
    case StopCategory::None: return "NONE";
    case StopCategory::Cat0: return "CAT0";
    case StopCategory::Cat1: return "CAT1";
    case StopCategory::Cat2: return "CAT2";
  }
  return "?";
}

}  // namespace safestate
