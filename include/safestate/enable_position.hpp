// SPDX-License-Identifier: Apache-2.0
// Enabling-device channel reading (design §2).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Position of one channel of the three-position enabling device (RSM-09). RELEASED is 0 so
/// that a zero-initialised (broken-wire) reading is the safe one.
enum class EnablePosition : std::uint8_t {
  Released,
  Middle,
  Panic,
};

inline constexpr std::size_t kEnablePositionCount = 3;

inline constexpr std::array<EnablePosition, kEnablePositionCount> kAllEnablePositions{
    EnablePosition::Released,
    EnablePosition::Middle,
    EnablePosition::Panic,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(EnablePosition v) noexcept {
  switch (v) {
    case EnablePosition::Released: return "RELEASED";
    case EnablePosition::Middle: return "MIDDLE";
    case EnablePosition::Panic: return "PANIC";
  }
  return "?";
}

}  // namespace safestate
