// SPDX-License-Identifier: Apache-2.0
// Outcome of the command handled in the last cycle (design §6, §7 `command_result`).
#pragma once

#include <cstdint>
#include <string_view>

#include "safestate/reject_reason.hpp"

namespace safestate {

/// NONE (the queue was empty), ACCEPTED, or the reject reason.
class CommandResult {
 public:
  enum class Outcome : std::uint8_t { None, Accepted, Rejected };

  constexpr CommandResult() noexcept = default;

  [[nodiscard]] static constexpr CommandResult none() noexcept { return {}; }
  [[nodiscard]] static constexpr CommandResult accepted() noexcept {
    return CommandResult{Outcome::Accepted, RejectReason::None};
  }
  [[nodiscard]] static constexpr CommandResult rejected(RejectReason reason) noexcept {
    return CommandResult{Outcome::Rejected, reason};
  }

  [[nodiscard]] constexpr Outcome outcome() const noexcept { return outcome_; }
  /// The reject reason; None unless outcome() is Rejected.
  [[nodiscard]] constexpr RejectReason reason() const noexcept { return reason_; }

  [[nodiscard]] constexpr bool operator==(const CommandResult& o) const noexcept {
    return outcome_ == o.outcome_ && reason_ == o.reason_;
  }
  [[nodiscard]] constexpr bool operator!=(const CommandResult& o) const noexcept { return !(*this == o); }

 private:
  constexpr CommandResult(Outcome outcome, RejectReason reason) noexcept : outcome_(outcome), reason_(reason) {}

  Outcome outcome_{Outcome::None};
  RejectReason reason_{RejectReason::None};
};

/// "NONE", "ACCEPTED" or the reason's name, e.g. "WRONG_STATE".
[[nodiscard]] constexpr std::string_view to_string(CommandResult r) noexcept {
  switch (r.outcome()) {
    case CommandResult::Outcome::None: return "NONE";
    case CommandResult::Outcome::Accepted: return "ACCEPTED";
    case CommandResult::Outcome::Rejected: return to_string(r.reason());
  }
  return "?";
}

}  // namespace safestate
