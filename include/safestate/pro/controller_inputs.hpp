// The environment of one controller tick: the sensor front end, the fan driver's fault
// line, the hardware watchdog and the platform's fatal-fault line (§6).
#pragma once

#include "safestate/pro/raw_sample.hpp"

namespace safestate::pro {

struct ControllerInputs {
  RawSample sample{};
  bool driver_fault{false};
  bool watchdog_ok{true};
  bool fatal_fault{false};
};

}  // namespace safestate::pro
