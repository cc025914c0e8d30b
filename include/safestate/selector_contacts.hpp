// SPDX-License-Identifier: Apache-2.0
// The three contacts of the hardware mode selector (design §2, RSM-02).
#pragma once

#include "safestate/selector_reading.hpp"

namespace safestate {

struct SelectorContacts {
  bool auto_{false};  ///< trailing underscore: `auto` is a keyword
  bool t1{false};
  bool t2{false};

  /// Exactly one closed contact gives its mode; none or several read Invalid.
  [[nodiscard]] constexpr SelectorReading reading() const noexcept {
    const int closed = (auto_ ? 1 : 0) + (t1 ? 1 : 0) + (t2 ? 1 : 0);
    if (closed != 1) {
      return SelectorReading::Invalid;
    }
    if (auto_) {
      return SelectorReading::Auto;
    }
    return t1 ? SelectorReading::T1 : SelectorReading::T2;
  }
};

}  // namespace safestate
