// SPDX-License-Identifier: Apache-2.0
// The two raw channels of a dual-channel safety input (design §2, RSM-04).
#pragma once

namespace safestate {

/// Channel A and channel B as read this cycle. Value-initialised = both channels at the
/// zero (tripped) level.
template <typename T>
struct ChannelPair {
  T a{};
  T b{};
};

}  // namespace safestate
