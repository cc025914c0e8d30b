// SPDX-License-Identifier: Apache-2.0
// Hardware mode selector with validity monitoring (design §2, §3, RSM-02).
#pragma once

#include <cstdint>

#include "safestate/selector_contacts.hpp"
#include "safestate/selector_reading.hpp"

namespace safestate {

/// Reads the three contacts each cycle and counts consecutive Invalid readings with the
/// same saturating counter as the dual-channel inputs:
///     selector_invalid := INVALID ? min(n + 1, D + 1) : 0
class ModeSelector {
 public:
  constexpr explicit ModeSelector(std::uint32_t discrepancy_cycles) noexcept
      : discrepancy_cycles_(discrepancy_cycles) {}

  constexpr void update(const SelectorContacts& contacts) noexcept {
    reading_ = contacts.reading();
    if (reading_ == SelectorReading::Invalid) {
      if (invalid_ <= discrepancy_cycles_) {
        ++invalid_;
      }
    } else {
      invalid_ = 0;
    }
  }

  /// Invalid before the first cycle.
  [[nodiscard]] constexpr SelectorReading reading() const noexcept { return reading_; }
  [[nodiscard]] constexpr bool valid() const noexcept { return reading_ != SelectorReading::Invalid; }
  /// Consecutive Invalid readings, saturated at D + 1.
  [[nodiscard]] constexpr std::uint32_t invalid_cycles() const noexcept { return invalid_; }
  /// Invalid for longer than the discrepancy time (fault SELECTOR_INVALID).
  [[nodiscard]] constexpr bool invalid_fault() const noexcept { return invalid_ > discrepancy_cycles_; }

 private:
  std::uint32_t discrepancy_cycles_;
  std::uint32_t invalid_{0};
  SelectorReading reading_{SelectorReading::Invalid};
};

}  // namespace safestate
