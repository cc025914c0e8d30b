// SPDX-License-Identifier: Apache-2.0
// The abstract inputs of one cycle (design §2 "Derived each cycle", §3): what the guards
// read, and what the model uses as its inputs.
#pragma once

#include "safestate/fault_code.hpp"
#include "safestate/selector_reading.hpp"
#include "safestate/speed_level.hpp"

namespace safestate {

struct DerivedInputs {
  bool estop_tripped{true};   ///< either E-stop channel open (1oo2)
  bool gate_open{true};       ///< either safeguard channel open
  bool enable_middle{false};  ///< both enabling channels MIDDLE
  bool enable_panic{false};   ///< either enabling channel PANIC
  SelectorReading selector{SelectorReading::Invalid};
  SpeedLevel speed{SpeedLevel::Zero};
  bool self_test_ok{false};
  bool servo_ready{false};
  bool drive_fault{false};
  bool fieldbus_ok{false};       ///< C24: FALSE = fieldbus / cycle watchdog lost
  bool operator_link_ok{false};  ///< C26: FALSE = the operator link's heartbeat expired
  /// K39 (ISO 10218-1 5.8.3): the enabling device was in PANIC (either channel) and has
  /// not been RELEASED (both channels) since; MIDDLE reached from PANIC does not enable.
  bool enable_release_required{false};
  /// C30: ContactorFeedback or BrakeFeedback once a feedback monitor latched (contactor
  /// first), else None.
  FaultCode feedback{FaultCode::None};
  /// First discrepancy fault in §3 order (E-stop, safeguard, enabling, selector), else None.
  FaultCode discrepancy{FaultCode::None};
};

}  // namespace safestate
