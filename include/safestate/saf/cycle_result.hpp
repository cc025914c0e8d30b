// SPDX-License-Identifier: Apache-2.0
// What one cycle did: the rows fired and the messages to send.
#pragma once

#include <string_view>

#include "safestate/saf/outbox.hpp"

namespace safestate::saf {

struct CycleResult {
  std::string_view state_row;    // §6 row id
  std::string_view control_row;  // §7 row id, "" in OPERATIONAL
  Outbox outbox{};
};

}  // namespace safestate::saf
