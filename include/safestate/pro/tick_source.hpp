// evt_timer_service (§1): the tick source. One tick is kTickPeriodMs; every timer of the
// controller is a tick count. The runtime advances it once per cycle; its status is the
// `timer` readiness gate.
#pragma once

#include <cstdint>

#include "safestate/pro/unit_status.hpp"

namespace safestate::pro {

inline constexpr std::uint32_t kTickPeriodMs = 100;

class TickSource {
 public:
  void start() noexcept { status_ = UnitStatus::ready; }
  void stop() noexcept { status_ = UnitStatus::stopped; }
  // The number of the tick that begins now (the first tick is 1).
  std::uint32_t advance() noexcept { return ++now_; }
  [[nodiscard]] std::uint32_t now() const noexcept { return now_; }
  [[nodiscard]] UnitStatus status() const noexcept { return status_; }

 private:
  std::uint32_t now_{0};
  UnitStatus status_{UnitStatus::init};
};

}  // namespace safestate::pro
