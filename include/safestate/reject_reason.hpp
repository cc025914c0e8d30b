// SPDX-License-Identifier: Apache-2.0
// Command reject reasons (design §6, RSM-13).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Reason code of a rejected command (§6, RSM-13) or of a full queue (§1, RSM-14).
enum class RejectReason : std::uint8_t {
  None,
  LockedOut,
  EstopPressed,
  WrongState,
  DriveFault,
  SelectorInvalid,
  SafeguardOpen,
  EnableNotMiddle,
  T2NotConfirmed,
  WrongMode,
  JogInAuto,
  InvalidArgument,
  QueueFull,
  ChannelTestPending,
};

inline constexpr std::size_t kRejectReasonCount = 14;

inline constexpr std::array<RejectReason, kRejectReasonCount> kAllRejectReasons{
    RejectReason::None,          RejectReason::LockedOut,          RejectReason::EstopPressed,
    RejectReason::WrongState,    RejectReason::DriveFault,         RejectReason::SelectorInvalid,
    RejectReason::SafeguardOpen, RejectReason::EnableNotMiddle,    RejectReason::T2NotConfirmed,
    RejectReason::WrongMode,     RejectReason::JogInAuto,          RejectReason::InvalidArgument,
    RejectReason::QueueFull,     RejectReason::ChannelTestPending,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(RejectReason v) noexcept {
  switch (v) {
    case RejectReason::None: return "NONE";
    case RejectReason::LockedOut: return "LOCKED_OUT";
    case RejectReason::EstopPressed: return "ESTOP_PRESSED";
    case RejectReason::WrongState: return "WRONG_STATE";
    case RejectReason::DriveFault: return "DRIVE_FAULT";
    case RejectReason::SelectorInvalid: return "SELECTOR_INVALID";
    case RejectReason::SafeguardOpen: return "SAFEGUARD_OPEN";
    case RejectReason::EnableNotMiddle: return "ENABLE_NOT_MIDDLE";
    case RejectReason::T2NotConfirmed: return "T2_NOT_CONFIRMED";
    case RejectReason::WrongMode: return "WRONG_MODE";
    case RejectReason::JogInAuto: return "JOG_IN_AUTO";
    case RejectReason::InvalidArgument: return "INVALID_ARGUMENT";
    case RejectReason::QueueFull: return "QUEUE_FULL";
    case RejectReason::ChannelTestPending: return "CHANNEL_TEST_PENDING";
  }
  return "?";
}

}  // namespace safestate
