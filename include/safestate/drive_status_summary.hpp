// SPDX-License-Identifier: Apache-2.0
// The drives' status words reduced to the manager's two drive inputs (design §2 "Drive
// status words"): servo_ready (C15) and drive_fault (C09, K04, K07).
#pragma once

#include <array>
#include <cstdint>

#include "safestate/cia402_status_word.hpp"
#include "safestate/joint_vector.hpp"

namespace safestate {

/// One status word per drive, drive i driving axis i + 1.
using DriveStatusWords = std::array<std::uint16_t, kAxisCount>;

struct DriveStatusSummary {
  std::array<DriveStatus, kAxisCount> drives{};
  bool servo_ready{false};  ///< every drive Operation enabled
  bool drive_fault{false};  ///< any drive in Fault, Fault reaction active, or Invalid
  bool warning{false};      ///< any drive's warning bit (diagnostics only)
};

[[nodiscard]] constexpr DriveStatusSummary summarize_drives(const DriveStatusWords& words) noexcept {
  DriveStatusSummary s;
  s.servo_ready = true;
  for (std::size_t i = 0; i < words.size(); ++i) {
    s.drives[i] = decode_status_word(words[i]);
    s.servo_ready = s.servo_ready && is_operation_enabled(s.drives[i]);
    s.drive_fault = s.drive_fault || is_faulted(s.drives[i]);
    s.warning = s.warning || s.drives[i].warning;
  }
  return s;
}

}  // namespace safestate
