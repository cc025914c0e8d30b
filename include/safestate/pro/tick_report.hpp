// What one controller tick did, for the demo, the tests and the conformance harness.
#pragma once

#include <cstdint>

#include "safestate/pro/dispatcher.hpp"
#include "safestate/pro/safety_result.hpp"
#include "safestate/pro/sensor_snapshot.hpp"
#include "safestate/pro/supervisor_row.hpp"
#include "safestate/pro/supervisor_state.hpp"

namespace safestate::pro {

struct TickReport {
  std::uint32_t tick{0};
  const SupervisorRow* row{nullptr};
  SupervisorState state{SupervisorState::init};
  DispatchRecord dispatched{};
  SensorSnapshot snapshot{};
  bool safety_ran{false};
  SafetyInput safety_input{SafetyInput::none};
  SafetyResult safety_result{SafetyResult::ok};
  std::uint8_t fan_output{0};
  bool load_enable{false};    // the equipment permissive after the tick (§4; false = outputs_disabled)
  std::uint8_t stop_step{0};  // the shutdown step waited for after this tick (0: none)
};

}  // namespace safestate::pro
