// SPDX-License-Identifier: Apache-2.0
// Resume target of a paused motion (design §4, RSM-11).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// The motion state a Cat 2 pause returns to (`resume_to`, §4).
enum class ResumeTarget : std::uint8_t {
  None,
  AutoRunning,
  ManualJogging,
};

inline constexpr std::size_t kResumeTargetCount = 3;

inline constexpr std::array<ResumeTarget, kResumeTargetCount> kAllResumeTargets{
    ResumeTarget::None,
    ResumeTarget::AutoRunning,
    ResumeTarget::ManualJogging,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(ResumeTarget v) noexcept {
  switch (v) {
    case ResumeTarget::None: return "NONE";
    case ResumeTarget::AutoRunning: return "AUTO_RUNNING";
    case ResumeTarget::ManualJogging: return "MANUAL_JOGGING";
  }
  return "?";
}

}  // namespace safestate
