#pragma once
// The models' observables of the hydraulic press (docs/design/hydraulic-press.md §6),
// shared by the chain press and the flat defective reference: motor, mode, step, outputs.
#include "safestate/chain/press_outputs.hpp"
#include "safestate/chain/press_step.hpp"

namespace safestate::chain {

struct PressObservation {
  bool motor = false;
  int mode = 0;  // 0 = none
  PressStep step = PressStep::none;
  PressOutputs outputs{};
};

}  // namespace safestate::chain
