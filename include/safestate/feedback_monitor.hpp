// SPDX-License-Identifier: Apache-2.0
// Monitoring of an output by its feedback contact (issue 29 item 10): the safety relay's
// auxiliary contact for the contactor, the brake's release feedback. Not yet wired into
// the manager (no row reads it): a component with its own tests.
#pragma once

#include <cstdint>

namespace safestate {

/// Which way the feedback disagreed when the monitor latched.
enum class FeedbackFault : std::uint8_t {
  None,
  StuckOn,   ///< commanded off, feedback still on (a welded contactor, a brake that stays released)
  StuckOff,  ///< commanded on, feedback still off (contactor not pulling in, brake not releasing)
};

/// A feedback must follow its command within `allowed_cycles` (the switching time of the
/// device, e.g. a contactor's 20-50 ms): each cycle with feedback != command counts, a
/// cycle with agreement restarts the count, and the `allowed_cycles + 1`-th disagreeing
/// cycle in a row latches a fault (as the discrepancy monitoring of §3). Latched: a welded
/// contact does not heal, only re-initialisation clears it.
/// The command is the output written in the previous cycle (what the device was told to do),
/// the feedback the input read in this one.
class FeedbackMonitor {
 public:
  explicit constexpr FeedbackMonitor(std::uint32_t allowed_cycles) noexcept : allowed_(allowed_cycles) {}

  /// One cycle; returns fault() after it.
  constexpr FeedbackFault update(bool commanded_on, bool feedback_on) noexcept {
    if (fault_ != FeedbackFault::None) return fault_;
    if (commanded_on == feedback_on) {
      disagree_ = 0;
      return fault_;
    }
    // A change of command restarts the count: the device is given its full switching time.
    if (disagree_ > 0 && commanded_on != last_command_) disagree_ = 0;
    last_command_ = commanded_on;
    if (disagree_ <= allowed_) ++disagree_;
    if (disagree_ > allowed_) fault_ = commanded_on ? FeedbackFault::StuckOff : FeedbackFault::StuckOn;
    return fault_;
  }

  [[nodiscard]] constexpr FeedbackFault fault() const noexcept { return fault_; }
  [[nodiscard]] constexpr std::uint32_t disagreeing_cycles() const noexcept { return disagree_; }

 private:
  std::uint32_t allowed_;
  std::uint32_t disagree_{0};
  bool last_command_{false};
  FeedbackFault fault_{FeedbackFault::None};
};

}  // namespace safestate
