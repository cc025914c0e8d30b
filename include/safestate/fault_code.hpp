// SPDX-License-Identifier: Apache-2.0
// Lockout fault codes (design §3, §5).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Why the manager is in ERROR_LOCKOUT (None in every other state). The four discrepancy
/// codes are listed in the order §3 checks them.
enum class FaultCode : std::uint8_t {
  None,
  SelfTestFailed,
  DiscrepancyEstop,
  DiscrepancySafeguard,
  DiscrepancyEnabling,
  SelectorInvalid,
  DriveFault,
  T1Overspeed,
  ArmingTimeout,
  StopTimeout,
  FieldbusLoss,
  StandstillViolation,
  ServoReadyLost,     ///< C27: the drives stopped reporting ready with the brakes released
  T2Overspeed,        ///< C29: measured TCP speed above the T2 limit in a T2 session
  ContactorFeedback,  ///< C30: the contactor's auxiliary contact disagreed beyond its switching time
  BrakeFeedback,      ///< C30: the brake feedback disagreed beyond its switching time
};

inline constexpr std::size_t kFaultCodeCount = 16;

inline constexpr std::array<FaultCode, kFaultCodeCount> kAllFaultCodes{
    FaultCode::None,
    FaultCode::SelfTestFailed,
    FaultCode::DiscrepancyEstop,
    FaultCode::DiscrepancySafeguard,
    FaultCode::DiscrepancyEnabling,
    FaultCode::SelectorInvalid,
    FaultCode::DriveFault,
    FaultCode::T1Overspeed,
    FaultCode::ArmingTimeout,
    FaultCode::StopTimeout,
    FaultCode::FieldbusLoss,
    FaultCode::StandstillViolation,
    FaultCode::ServoReadyLost,
    FaultCode::T2Overspeed,
    FaultCode::ContactorFeedback,
    FaultCode::BrakeFeedback,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(FaultCode v) noexcept {
  switch (v) {
    case FaultCode::None: return "NONE";
    case FaultCode::SelfTestFailed: return "SELF_TEST_FAILED";
    case FaultCode::DiscrepancyEstop: return "DISCREPANCY_ESTOP";
    case FaultCode::DiscrepancySafeguard: return "DISCREPANCY_SAFEGUARD";
    case FaultCode::DiscrepancyEnabling: return "DISCREPANCY_ENABLING";
    case FaultCode::SelectorInvalid: return "SELECTOR_INVALID";
    case FaultCode::DriveFault: return "DRIVE_FAULT";
    case FaultCode::T1Overspeed: return "T1_OVERSPEED";
    case FaultCode::ArmingTimeout: return "ARMING_TIMEOUT";
    case FaultCode::StopTimeout: return "STOP_TIMEOUT";
    case FaultCode::FieldbusLoss: return "FIELDBUS_LOSS";
    case FaultCode::StandstillViolation: return "STANDSTILL_VIOLATION";
    case FaultCode::ServoReadyLost: return "SERVO_READY_LOST";
    case FaultCode::T2Overspeed: return "T2_OVERSPEED";
    case FaultCode::ContactorFeedback: return "CONTACTOR_FEEDBACK";
    case FaultCode::BrakeFeedback: return "BRAKE_FEEDBACK";
  }
  return "?";
}

}  // namespace safestate
