#pragma once
// Result of StateChain::request (docs/design/state-chain.md §4): the first failing check.
#include <cstdint>

namespace safestate::chain {

enum class RequestResult : std::uint8_t {
  ok,               // exited the source, entered the target
  unknown_state,    // an index outside the table
  source_inactive,  // the source is not active
  cross_level,      // source and target are not siblings (SCH-02)
  target_active,    // the target is active and not the source (SCH-02)
};

[[nodiscard]] constexpr const char* to_string(RequestResult r) noexcept {
  switch (r) {
    case RequestResult::ok: return "ok";
    case RequestResult::unknown_state: return "unknown_state";
    case RequestResult::source_inactive: return "source_inactive";
    case RequestResult::cross_level: return "cross_level";
    case RequestResult::target_active: return "target_active";
  }
  return "?";
}

}  // namespace safestate::chain
