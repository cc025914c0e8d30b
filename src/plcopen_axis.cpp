// SPDX-License-Identifier: Apache-2.0
#include "safestate/plcopen_axis.hpp"

namespace safestate {

AxisTransition PlcopenAxis::request(AxisEvent event) noexcept {
  const AxisTransition t = transition(state_, event, powered_);
  if (!t.accepted()) {
    return t;
  }
  switch (event) {
    case AxisEvent::PowerOn: powered_ = true; break;
    case AxisEvent::PowerOff: powered_ = false; break;
    default: break;
  }
  state_ = t.next;
  return t;
}

void PlcopenAxis::track(AxisState desired, bool speed_zero) noexcept {
  const AxisState next = step_toward(state_, desired, speed_zero);
  // MC_Power follows the step: leaving Disabled means MC_Power(on), entering Disabled means
  // MC_Power(off). ErrorStop keeps the power status it had (the drive removes torque itself).
  if (state_ == AxisState::Disabled && next != AxisState::Disabled && next != AxisState::ErrorStop) {
    powered_ = true;
  } else if (next == AxisState::Disabled) {
    powered_ = false;
  }
  state_ = next;
}

}  // namespace safestate
