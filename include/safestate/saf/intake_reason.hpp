// SPDX-License-Identifier: Apache-2.0
// Why the intake rejected a datagram before the core saw it (design §14): the codec's
// reasons (§10) and those of sender binding, freshness, authentication and flood, and
// of the authenticated subsystem link (§15).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "safestate/saf/decode_error.hpp"

namespace safestate::saf {

enum class IntakeReason : std::uint8_t {
  None = 0,
  Truncated,  // the seven codec reasons, in DecodeError's order
  Oversized,
  TrailingBytes,
  UnknownId,
  BadLength,
  FieldRange,
  NotIncoming,
  EstopWrongSource,       // Set Estop not from the configured Safety Client address and port
  EstopWrongComponent,    // Set Estop naming another component id than the configured client's
  EstopUnsequenced,       // the seed's Set Estop (no sequence) where the extension is required
  EstopUnauthenticated,   // a Set Estop without MAC where a key is configured
  EstopBadMac,            // a MAC that does not verify (or a MAC where no key is configured)
  EstopReplay,            // sequence not above the highest accepted, within the replay window
  EstopStale,             // sequence older than the replay window
  EstopClearInOverflow,   // a clear Set Estop while the client socket overflowed or is backlogged
  ReportWrongSource,      // a subsystem message not from the configured subsystem, or on the client socket
  ReportUnauthenticated,  // with a key: a datagram on the subsystem socket without the link trailer (§15)
  ReportBadMac,           // with a key: the link trailer's MAC does not verify (key or direction)
  ReportReplay,           // with a key: link sequence not above the highest accepted, within the window
  ReportStale,            // with a key: link sequence older than the window
};

inline constexpr std::size_t kIntakeReasonCount = 21;

[[nodiscard]] constexpr IntakeReason intake_reason_of(DecodeError e) noexcept {
  return static_cast<IntakeReason>(static_cast<std::uint8_t>(e));
}

[[nodiscard]] constexpr std::string_view to_string(IntakeReason r) noexcept {
  switch (r) {
    case IntakeReason::None: return "NONE";
    case IntakeReason::Truncated: return "TRUNCATED";
    case IntakeReason::Oversized: return "OVERSIZED";
    case IntakeReason::TrailingBytes: return "TRAILING_BYTES";
    case IntakeReason::UnknownId: return "UNKNOWN_ID";
    case IntakeReason::BadLength: return "BAD_LENGTH";
    case IntakeReason::FieldRange: return "FIELD_RANGE";
    case IntakeReason::NotIncoming: return "NOT_INCOMING";
    case IntakeReason::EstopWrongSource: return "ESTOP_WRONG_SOURCE";
    case IntakeReason::EstopWrongComponent: return "ESTOP_WRONG_COMPONENT";
    case IntakeReason::EstopUnsequenced: return "ESTOP_UNSEQUENCED";
    case IntakeReason::EstopUnauthenticated: return "ESTOP_UNAUTHENTICATED";
    case IntakeReason::EstopBadMac: return "ESTOP_BAD_MAC";
    case IntakeReason::EstopReplay: return "ESTOP_REPLAY";
    case IntakeReason::EstopStale: return "ESTOP_STALE";
    case IntakeReason::EstopClearInOverflow: return "ESTOP_CLEAR_IN_OVERFLOW";
    case IntakeReason::ReportWrongSource: return "REPORT_WRONG_SOURCE";
    case IntakeReason::ReportUnauthenticated: return "REPORT_UNAUTHENTICATED";
    case IntakeReason::ReportBadMac: return "REPORT_BAD_MAC";
    case IntakeReason::ReportReplay: return "REPORT_REPLAY";
    case IntakeReason::ReportStale: return "REPORT_STALE";
  }
  return "?";
}

static_assert(static_cast<std::size_t>(IntakeReason::NotIncoming) + 1 == kDecodeErrorCount);
static_assert(static_cast<std::size_t>(IntakeReason::ReportStale) + 1 == kIntakeReasonCount);

}  // namespace safestate::saf
