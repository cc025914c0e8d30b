// SPDX-License-Identifier: Apache-2.0
// A simulated EtherCAT master for tests, the demo cell and the conformance binding (never
// part of the control cycle's product code): it turns the plant's levels (bus healthy,
// drives ready, a drive faulted) into the process image a real master would deliver, which
// the manager then decodes and supervises itself (design §2).
#pragma once

#include <cstdint>

#include "safestate/drive_bus_image.hpp"
#include "safestate/fieldbus_watchdog.hpp"

namespace safestate::sim {

/// The plant's drive and bus levels (the model's abstract inputs servo_ready, drive_fault,
/// fieldbus_ok).
struct BusLevels {
  bool fieldbus_ok{true};
  bool servo_ready{true};
  bool drive_fault{false};
};

inline constexpr std::uint16_t kOperationEnabledWord = 0x0037;  ///< operation enabled, voltage on
inline constexpr std::uint16_t kSwitchedOnWord = 0x0033;        ///< switched on, not enabled
inline constexpr std::uint16_t kFaultWord = 0x0008;             ///< fault

/// The next frame for the manager whose watchdog is `w`: a healthy bus delivers a fresh,
/// complete frame (counter + 1, expected WKC); a lost bus delivers nothing new (counter
/// unchanged, WKC 0). A drive fault shows as the fault state of drive 1 (CiA 402 excludes
/// Operation enabled then, so servo_ready reads false with it).
[[nodiscard]] inline DriveBusImage bus_image(const FieldbusWatchdog& w, const BusLevels& l) noexcept {
  DriveBusImage img;
  img.status_words.fill(l.servo_ready ? kOperationEnabledWord : kSwitchedOnWord);
  if (l.drive_fault) img.status_words[0] = kFaultWord;
  if (l.fieldbus_ok) {
    img.cycle_counter = w.has_reference() ? static_cast<std::uint16_t>(w.last_counter() + 1U) : std::uint16_t{1};
    img.working_counter = w.expected_working_counter();
  } else {
    img.cycle_counter = w.last_counter();
    img.working_counter = 0;
  }
  return img;
}

/// A master with its own frame counter, for a plant driving several implementations side
/// by side (the bench): a healthy bus advances the counter by one per cycle.
class BusMaster {
 public:
  explicit constexpr BusMaster(std::uint16_t expected_working_counter) noexcept : wkc_(expected_working_counter) {}

  [[nodiscard]] DriveBusImage next(const BusLevels& l) noexcept {
    DriveBusImage img;
    img.status_words.fill(l.servo_ready ? kOperationEnabledWord : kSwitchedOnWord);
    if (l.drive_fault) img.status_words[0] = kFaultWord;
    if (l.fieldbus_ok) ++counter_;
    img.cycle_counter = counter_;
    img.working_counter = l.fieldbus_ok ? wkc_ : std::uint16_t{0};
    return img;
  }

 private:
  std::uint16_t wkc_;
  std::uint16_t counter_{0};
};

}  // namespace safestate::sim
