#pragma once
// One scan's inputs of the hydraulic press (docs/design/hydraulic-press.md §2), shared by
// the chain press and the flat defective reference.
#include <cstdint>

namespace safestate::chain {

// Buttons are edges (true in the scan they are pressed).
struct PressInputs {
  bool motor_on = false;    // MON
  bool motor_off = false;   // MOFF (wins over motor_on)
  bool start = false;       // Star (two buttons in series)
  bool ret = false;         // RET: back to Ready
  bool step_done = false;   // the limit switch / sensor completing the active stroke
  std::uint8_t mode = 0;    // mode selector edge: 1..3, 0 = no change
  bool continuous = false;  // run-kind switch (level): continuous vs single-step
  bool temp_high = false;   // oil above the cooling limit
  bool temp_ok = false;     // oil back under it
};

}  // namespace safestate::chain
