// SPDX-License-Identifier: Apache-2.0
// What the Reset command's interlock remembers between cycles (design §6, K36, K37).
#pragma once

#include <cstdint>

namespace safestate {

/// K36: a Reset is accepted only if it was submitted after the E-stop release. At the
/// release (C07) every queued command was submitted before it; each pop consumes one.
/// K37: a Reset is accepted only if both E-stop channels were seen open (tripped) since the
/// last accepted Reset: a one-channel demand shorter than the discrepancy time would
/// otherwise leave a stuck channel undetected (ISO 13849-1 single-fault detection).
struct ResetInterlock {
  std::uint32_t stale_commands{0};  ///< queued commands submitted before the last release
  bool estop_tested_a{false};       ///< channel A seen open since the last accepted Reset
  bool estop_tested_b{false};       ///< channel B likewise
};

}  // namespace safestate
