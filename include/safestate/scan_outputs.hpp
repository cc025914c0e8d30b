// SPDX-License-Identifier: Apache-2.0
// Outputs of one scan cycle (design §7, RSM-16).
#pragma once

#include <array>
#include <cstdint>

#include "safestate/joint_vector.hpp"
#include "safestate/plcopen_axis.hpp"

namespace safestate {

/// Computed from the state after the cycle's command (§7). All FALSE/0 before the first cycle.
struct ScanOutputs {
  bool contactor_closed{false};              ///< state is powered
  bool drive_enable{false};                  ///< state is powered
  bool brake_release{false};                 ///< state is powered
  bool ramp_down_request{false};             ///< state = STOPPING
  bool reset_lamp{false};                    ///< state = ESTOP_RESET_NEEDED
  std::int32_t commanded_speed_mm_s{0};      ///< jog speed in MANUAL_JOGGING, else 0
  std::array<AxisState, kAxisCount> axes{};  ///< PLCopen axis states after this cycle (§8)

  [[nodiscard]] bool operator==(const ScanOutputs& o) const noexcept {
    return contactor_closed == o.contactor_closed && drive_enable == o.drive_enable &&
           brake_release == o.brake_release && ramp_down_request == o.ramp_down_request && reset_lamp == o.reset_lamp &&
           commanded_speed_mm_s == o.commanded_speed_mm_s && axes == o.axes;
  }
  [[nodiscard]] bool operator!=(const ScanOutputs& o) const noexcept { return !(*this == o); }
};

}  // namespace safestate
