// The data the units of one controller hand each other within a tick, in dispatch order
// (§1, §2, §4): the environment's inputs, monitoring's snapshot, control's command,
// safety's output, the image diagnostics publishes. Events carry signals; this carries
// the values (a one-slot mailbox per value: the newest wins, §2).
#pragma once

#include <cstdint>

#include "safestate/pro/clear_outcome.hpp"
#include "safestate/pro/process_image.hpp"
#include "safestate/pro/raw_sample.hpp"
#include "safestate/pro/safety_result.hpp"
#include "safestate/pro/sensor_snapshot.hpp"
#include "safestate/pro/supervisor_state.hpp"

namespace safestate::pro {

struct CycleData {
  std::uint32_t tick{0};
  SupervisorState supervisor{SupervisorState::init};
  RawSample sample{};                 // input: the sensor front end
  bool driver_fault{false};           // input: the fan driver's fault line
  SensorSnapshot snapshot{};          // monitoring -> safety, control
  bool clear_pending{false};          // comms -> monitoring's next snapshot
  std::uint8_t control_command{100};  // control -> safety's output gate
  std::uint8_t fan_output{100};       // safety -> the fan driver
  bool load_enable{false};            // safety -> the equipment permissive (§4)
  bool outputs_held_safe{false};      // control, from shutdown step 1 on (§9)
  SafetyResult safety_result{SafetyResult::ok};
  ClearOutcome last_clear{ClearOutcome::none};
  ProcessImage image{};  // diagnostics -> comms
};

}  // namespace safestate::pro
