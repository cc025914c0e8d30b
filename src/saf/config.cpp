// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/config.hpp"

#include <cmath>

namespace safestate::saf {
namespace {

bool usable_time(double s) noexcept { return std::isfinite(s) && s > 0.0; }

/// max(1, ceil(p / cycle - 1e-9)): never shorter than asked; 1e-9 absorbs 0.1 / 0.05.
double cycles_of(double seconds, double cycle) noexcept {
  const double c = std::ceil(seconds / cycle - 1e-9);
  return c < 1.0 ? 1.0 : c;
}

}  // namespace

ConfigError Config::validate() const noexcept {
  if (!usable_time(cycle_interval_s)) return ConfigError::CycleIntervalInvalid;
  for (double t : {estop_timeout_s, report_data_timeout_s, message_interval_s, check_interval_s}) {
    if (!usable_time(t)) return ConfigError::TimeInvalid;
    if (cycles_of(t, cycle_interval_s) > static_cast<double>(kMaxTimerCycles)) {
      return ConfigError::TooManyCycles;
    }
  }
  return ConfigError::None;
}

Timing Config::timing() const noexcept {
  const auto c = [this](double s) { return static_cast<std::uint32_t>(cycles_of(s, cycle_interval_s)); };
  return Timing{c(estop_timeout_s), c(report_data_timeout_s), c(message_interval_s), c(check_interval_s)};
}

}  // namespace safestate::saf
