// SPDX-License-Identifier: Apache-2.0
// The observable state of the service: the model's variables (design §4, §12).
#pragma once

#include <cstdint>

#include "safestate/saf/service_values.hpp"

namespace safestate::saf {

struct Observable {
  SafState state = SafState::Pairing;
  EstopView estop = EstopView::None;
  std::uint32_t estop_age = 0;
  HealthView health = HealthView::None;
  std::uint32_t health_age = 0;
  ControlStatus control = ControlStatus::Released;
  std::uint32_t control_age = 0;
  OutRequest out_request = OutRequest::None;
  OutSetState out_set_state = OutSetState::None;
  bool alarm = false;         // the authority contest is lost (K03, K06), design §7
  bool resend = false;        // a re-send of Set Subsystem State(EMERGENCY) is due, design §7
  std::uint32_t set_age = 0;  // cycles since the last Set Subsystem State(EMERGENCY), to Mi

  friend constexpr bool operator==(const Observable& a, const Observable& b) noexcept {
    return a.state == b.state && a.estop == b.estop && a.estop_age == b.estop_age && a.health == b.health &&
           a.health_age == b.health_age && a.control == b.control && a.control_age == b.control_age &&
           a.out_request == b.out_request && a.out_set_state == b.out_set_state && a.alarm == b.alarm &&
           a.resend == b.resend && a.set_age == b.set_age;
  }
};

}  // namespace safestate::saf
