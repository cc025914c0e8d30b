// SPDX-License-Identifier: Apache-2.0
// Which table rows fired in the last cycle (for the conformance row-coverage audit).
#pragma once

#include "safestate/transition_row.hpp"

namespace safestate {

struct FiredRows {
  const TransitionRow* cycle{nullptr};    ///< the §5 row; null before the first cycle
  const TransitionRow* command{nullptr};  ///< the §6 row; null when the cycle popped no command
};

}  // namespace safestate
