// SPDX-License-Identifier: Apache-2.0
// Status record for the operator interface (design §7, RSM-16).
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/command_result.hpp"
#include "safestate/fault_code.hpp"
#include "safestate/operating_mode.hpp"
#include "safestate/reject_reason.hpp"
#include "safestate/resume_target.hpp"
#include "safestate/selector_reading.hpp"
#include "safestate/state_id.hpp"
#include "safestate/stop_category.hpp"

namespace safestate {

/// Every field the conformance suite compares with the model after each step.
struct StatusRecord {
  StateId state{StateId::Boot};
  SelectorReading selector{SelectorReading::Invalid};  ///< reading of the last cycle
  OperatingMode session_mode{OperatingMode::None};
  StopCategory stop_category{StopCategory::None};  ///< category of the most recent stop row
  FaultCode fault_code{FaultCode::None};
  RejectReason last_reject_reason{RejectReason::None};
  CommandResult command_result{};  ///< outcome of the last cycle's command
  // Diagnostics.
  std::uint32_t estop_mismatch{0};
  std::uint32_t safeguard_mismatch{0};
  std::uint32_t enabling_mismatch{0};
  std::uint32_t selector_invalid{0};
  std::uint32_t state_cycles{0};
  bool t2_confirmed{false};
  ResumeTarget resume_to{ResumeTarget::None};
  std::int32_t jog_axis{0};
  std::int32_t jog_direction{0};
  std::int32_t jog_speed_mm_s{0};
  std::size_t queue_length{0};
  std::uint32_t stale_commands{0};       ///< K36: queued commands submitted before the E-stop release
  bool estop_tested_a{false};            ///< K37: E-stop channel A seen open since the last Reset
  bool estop_tested_b{false};            ///< K37: likewise channel B
  bool enable_release_required{false};   ///< K39: PANIC seen since the enabling device was last RELEASED
  std::uint32_t contactor_fb_cycles{0};  ///< C30: cycles the contactor feedback disagreed in a row
  std::uint32_t brake_fb_cycles{0};      ///< C30: likewise the brake feedback

  [[nodiscard]] bool operator==(const StatusRecord& o) const noexcept {
    return state == o.state && selector == o.selector && session_mode == o.session_mode &&
           stop_category == o.stop_category && fault_code == o.fault_code &&
           last_reject_reason == o.last_reject_reason && command_result == o.command_result &&
           estop_mismatch == o.estop_mismatch && safeguard_mismatch == o.safeguard_mismatch &&
           enabling_mismatch == o.enabling_mismatch && selector_invalid == o.selector_invalid &&
           state_cycles == o.state_cycles && t2_confirmed == o.t2_confirmed && resume_to == o.resume_to &&
           jog_axis == o.jog_axis && jog_direction == o.jog_direction && jog_speed_mm_s == o.jog_speed_mm_s &&
           queue_length == o.queue_length && stale_commands == o.stale_commands && estop_tested_a == o.estop_tested_a &&
           estop_tested_b == o.estop_tested_b && enable_release_required == o.enable_release_required &&
           contactor_fb_cycles == o.contactor_fb_cycles && brake_fb_cycles == o.brake_fb_cycles;
  }
  [[nodiscard]] bool operator!=(const StatusRecord& o) const noexcept { return !(*this == o); }
};

}  // namespace safestate
