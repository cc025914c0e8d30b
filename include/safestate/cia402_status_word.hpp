// SPDX-License-Identifier: Apache-2.0
// Decoding of one drive's CiA 402 status word (object 0x6041; IEC 61800-7-201), design §2
// "Drive status words": the state by the standard's mask/value table, and the flag bits.
#pragma once

#include <array>
#include <cstdint>

#include "safestate/cia402_state.hpp"

namespace safestate {

/// Status word bits (IEC 61800-7-201, CiA 402 object 0x6041).
namespace cia402_bit {
inline constexpr std::uint16_t kReadyToSwitchOn = 1U << 0U;
inline constexpr std::uint16_t kSwitchedOn = 1U << 1U;
inline constexpr std::uint16_t kOperationEnabled = 1U << 2U;
inline constexpr std::uint16_t kFault = 1U << 3U;
inline constexpr std::uint16_t kVoltageEnabled = 1U << 4U;
inline constexpr std::uint16_t kQuickStop = 1U << 5U;  ///< active low: 0 = quick stop in progress
inline constexpr std::uint16_t kSwitchOnDisabled = 1U << 6U;
inline constexpr std::uint16_t kWarning = 1U << 7U;
}  // namespace cia402_bit

/// One row of the standard's state table: the state whose bits under `mask` equal `value`.
struct Cia402Pattern {
  std::uint16_t mask;
  std::uint16_t value;
  Cia402State state;
};

/// The CiA 402 state table (x = don't care):
///   Not ready to switch on  xxxx xxxx x0xx 0000
///   Switch on disabled      xxxx xxxx x1xx 0000
///   Ready to switch on      xxxx xxxx x01x 0001
///   Switched on             xxxx xxxx x01x 0011
///   Operation enabled       xxxx xxxx x01x 0111
///   Quick stop active       xxxx xxxx x00x 0111
///   Fault reaction active   xxxx xxxx x0xx 1111
///   Fault                   xxxx xxxx x0xx 1000
/// The patterns are disjoint (checked below), so the order does not matter.
inline constexpr std::array<Cia402Pattern, 8> kCia402Patterns{{
    {0x004F, 0x0000, Cia402State::NotReadyToSwitchOn},
    {0x004F, 0x0040, Cia402State::SwitchOnDisabled},
    {0x006F, 0x0021, Cia402State::ReadyToSwitchOn},
    {0x006F, 0x0023, Cia402State::SwitchedOn},
    {0x006F, 0x0027, Cia402State::OperationEnabled},
    {0x006F, 0x0007, Cia402State::QuickStopActive},
    {0x004F, 0x000F, Cia402State::FaultReactionActive},
    {0x004F, 0x0008, Cia402State::Fault},
}};

/// What one status word says.
struct DriveStatus {
  Cia402State state{Cia402State::NotReadyToSwitchOn};
  bool warning{false};          ///< bit 7: a warning, not a fault (diagnostics only)
  bool voltage_enabled{false};  ///< bit 4: DC link voltage present
  bool quick_stop{false};       ///< bit 5 read as "quick stop in progress" (the bit is active low)
};

[[nodiscard]] constexpr Cia402State cia402_state(std::uint16_t status_word) noexcept {
  for (const Cia402Pattern& p : kCia402Patterns) {
    if ((status_word & p.mask) == p.value) return p.state;
  }
  return Cia402State::Invalid;
}

[[nodiscard]] constexpr DriveStatus decode_status_word(std::uint16_t status_word) noexcept {
  return DriveStatus{cia402_state(status_word), (status_word & cia402_bit::kWarning) != 0U,
                     (status_word & cia402_bit::kVoltageEnabled) != 0U, (status_word & cia402_bit::kQuickStop) == 0U};
}

/// Ready for motion: only Operation enabled (power on the motor, set-points followed).
[[nodiscard]] constexpr bool is_operation_enabled(const DriveStatus& d) noexcept {
  return d.state == Cia402State::OperationEnabled;
}

/// A fault: the drive's Fault or Fault reaction active state, or a word matching no state.
[[nodiscard]] constexpr bool is_faulted(const DriveStatus& d) noexcept {
  return d.state == Cia402State::Fault || d.state == Cia402State::FaultReactionActive ||
         d.state == Cia402State::Invalid;
}

namespace cia402_check {
/// No status word matches two patterns: every word decodes to exactly one state or Invalid.
[[nodiscard]] constexpr bool patterns_disjoint() noexcept {
  for (std::uint32_t w = 0; w < 0x80U; ++w) {  // the patterns read bits 0-6 only
    int matches = 0;
    for (const Cia402Pattern& p : kCia402Patterns) {
      if ((w & p.mask) == p.value) ++matches;
    }
    if (matches > 1) return false;
  }
  return true;
}
}  // namespace cia402_check

static_assert(cia402_check::patterns_disjoint(), "the CiA 402 state patterns must be disjoint");
static_assert(cia402_state(0x0000) == Cia402State::NotReadyToSwitchOn, "a zero word is not ready, not a fault");

}  // namespace safestate
