#pragma once
// The entry and exit calls of one engine step, in call order (docs/design/state-chain.md
// §6): what the model's `log` records, kept so conformance can compare the C++ calls
// with the model's (SCH-01 entry top-down, exit bottom-up; SCH-02 a rejection calls
// nothing). Fixed capacity, no heap: calls beyond it are counted as an overflow.
#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/chain/state_def.hpp"

namespace safestate::chain {

enum class CallKind : std::uint8_t { entry, exit };

[[nodiscard]] constexpr const char* to_string(CallKind k) noexcept { return k == CallKind::entry ? "entry" : "exit"; }

struct Call {
  CallKind kind;
  StateIndex state;
};

template <std::size_t Capacity>
class CallLog {
 public:
  void clear() noexcept {
    size_ = 0;
    overflow_ = false;
  }
  void push(CallKind k, StateIndex s) noexcept {
    if (size_ < Capacity) {
      calls_[size_++] = Call{k, s};
    } else {
      overflow_ = true;
    }
  }
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] const Call& operator[](std::size_t i) const noexcept { return calls_[i]; }
  // More calls were made than the log holds (several requests in one step).
  [[nodiscard]] bool overflow() const noexcept { return overflow_; }

 private:
  std::array<Call, Capacity> calls_{};
  std::size_t size_ = 0;
  bool overflow_ = false;
};

}  // namespace safestate::chain
