// SPDX-License-Identifier: Apache-2.0
// Parsing of the upper-case enum names (the strings the conformance suite compares).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace safestate {

/// Inverse of `to_string` for an enum whose every value is listed in `all`.
/// Used by the Python binding and the tests; never on the control path.
template <typename E, std::size_t N>
[[nodiscard]] constexpr std::optional<E> enum_from_string(std::string_view text, const std::array<E, N>& all) noexcept {
  for (const E value : all) {
    if (to_string(value) == text) {
      return value;
    }
  }
  return std::nullopt;
}

}  // namespace safestate
