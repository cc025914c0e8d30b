// SPDX-License-Identifier: Apache-2.0
// Result of submitting a command into the queue (design §1).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Result of SystemStateManager::submit() (§1, RSM-14). Spelled as on the design page.
enum class SubmitResult : std::uint8_t {
  queued,
  queue_full,
};

inline constexpr std::size_t kSubmitResultCount = 2;

inline constexpr std::array<SubmitResult, kSubmitResultCount> kAllSubmitResults{
    SubmitResult::queued,
    SubmitResult::queue_full,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(SubmitResult v) noexcept {
  switch (v) {
    case SubmitResult::queued: return "QUEUED";
    case SubmitResult::queue_full: return "QUEUE_FULL";
  }
  return "?";
}

}  // namespace safestate
