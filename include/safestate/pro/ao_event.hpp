// One event in an active object's queue: a signal, the tick it belongs to and a
// two-byte payload whose meaning depends on the signal (operating_status: protection
// state, override; fault_event: cause). Trivially copyable: queues copy it by value.
#pragma once

#include <cstdint>

#include "safestate/pro/ao_signal.hpp"

namespace safestate::pro {

struct AoEvent {
  AoSignal signal{AoSignal::tick};
  std::uint32_t tick{0};
  std::uint8_t arg0{0};
  std::uint8_t arg1{0};
};

}  // namespace safestate::pro
