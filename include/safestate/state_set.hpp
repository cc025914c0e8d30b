// SPDX-License-Identifier: Apache-2.0
// A set of leaf states: the "source" and "target" columns of the transition table.
#pragma once

#include <cstdint>
#include <initializer_list>

#include "safestate/state_id.hpp"

namespace safestate {

class StateSet {
 public:
  constexpr StateSet() noexcept = default;
  constexpr StateSet(std::initializer_list<StateId> states) noexcept {
    for (const StateId s : states) {
      bits_ = static_cast<std::uint16_t>(bits_ | bit(s));
    }
  }

  /// Every leaf state ("any" in the design tables).
  [[nodiscard]] static constexpr StateSet all() noexcept {
    StateSet set;
    for (const StateId s : kAllStates) {
      set.bits_ = static_cast<std::uint16_t>(set.bits_ | bit(s));
    }
    return set;
  }

  /// Every leaf state but the listed ones ("state ≠ X", "any but X").
  [[nodiscard]] static constexpr StateSet all_except(std::initializer_list<StateId> states) noexcept {
    StateSet set = all();
    for (const StateId s : states) {
      set.bits_ = static_cast<std::uint16_t>(set.bits_ & ~bit(s));
    }
    return set;
  }

  /// ARMING, OPERATIONAL (its four sub-states), STOPPING, HOLD.
  [[nodiscard]] static constexpr StateSet powered() noexcept {
    StateSet set;
    for (const StateId s : kAllStates) {
      if (is_powered(s)) {
        set.bits_ = static_cast<std::uint16_t>(set.bits_ | bit(s));
      }
    }
    return set;
  }

  [[nodiscard]] constexpr StateSet operator|(StateSet other) const noexcept {
    StateSet set;
    set.bits_ = static_cast<std::uint16_t>(bits_ | other.bits_);
    return set;
  }

  [[nodiscard]] constexpr bool contains(StateId s) const noexcept { return (bits_ & bit(s)) != 0U; }
  [[nodiscard]] constexpr bool empty() const noexcept { return bits_ == 0U; }
  [[nodiscard]] constexpr std::uint16_t bits() const noexcept { return bits_; }
  [[nodiscard]] constexpr bool operator==(StateSet other) const noexcept { return bits_ == other.bits_; }
  [[nodiscard]] constexpr bool operator!=(StateSet other) const noexcept { return bits_ != other.bits_; }

 private:
  [[nodiscard]] static constexpr std::uint16_t bit(StateId s) noexcept {
    return static_cast<std::uint16_t>(1U << static_cast<unsigned>(s));
  }

  std::uint16_t bits_{0};
};

}  // namespace safestate
