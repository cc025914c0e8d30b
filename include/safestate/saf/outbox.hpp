// SPDX-License-Identifier: Apache-2.0
// The messages one cycle sends (design §8): at most one per outgoing type.
#pragma once

#include <array>
#include <cstddef>

#include "safestate/saf/codec.hpp"

namespace safestate::saf {

inline constexpr std::size_t kMaxOutboundPerCycle = 4;

struct Outbox {
  std::array<Message, kMaxOutboundPerCycle> messages{};
  std::size_t count = 0;
};

}  // namespace safestate::saf
