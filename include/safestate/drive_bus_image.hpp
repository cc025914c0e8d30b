// SPDX-License-Identifier: Apache-2.0
// What one cycle reads from the EtherCAT process image (design §2 "Drive status words",
// "Fieldbus watchdog"): raw values, decoded and supervised in the core.
#pragma once

#include <cstdint>

#include "safestate/drive_status_summary.hpp"

namespace safestate {

/// Zero-initialised it is the safe reading: WKC 0 is a fieldbus loss (C24), status words 0
/// are "not ready to switch on".
struct DriveBusImage {
  DriveStatusWords status_words{};   ///< CiA 402 status word (0x6041) of drive 1..6
  std::uint16_t cycle_counter{0};    ///< the master's bus cycle counter of this frame
  std::uint16_t working_counter{0};  ///< the frame's EtherCAT working counter
};

}  // namespace safestate
