// SPDX-License-Identifier: Apache-2.0
// The six parameters of SAF-04 and their conversion into cycles (design §3).
#pragma once

#include <cstdint>
#include <string_view>

namespace safestate::saf {

/// Timers in whole cycles, as the service and the model use them.
struct Timing {
  std::uint32_t estop_timeout = 2;         // EstopTimeoutCycles
  std::uint32_t report_data_timeout = 40;  // ReportDataTimeoutCycles
  std::uint32_t message_interval = 10;     // MessageIntervalCycles
  std::uint32_t check_interval = 20;       // CheckIntervalCycles
};

enum class ConfigError : std::uint8_t {
  None,
  CycleIntervalInvalid,  // <= 0, NaN or infinite
  TimeInvalid,           // a time parameter <= 0, NaN or infinite
  TooManyCycles,         // a time converts to more than kMaxTimerCycles
};

[[nodiscard]] constexpr std::string_view to_string(ConfigError e) noexcept {
  switch (e) {
    case ConfigError::None: return "NONE";
    case ConfigError::CycleIntervalInvalid: return "CYCLE_INTERVAL_INVALID";
    case ConfigError::TimeInvalid: return "TIME_INVALID";
    case ConfigError::TooManyCycles: return "TOO_MANY_CYCLES";
  }
  return "?";
}

inline constexpr std::uint32_t kMaxTimerCycles = 65535;

/// SAF-04, in the seed's units (seconds), with the seed's defaults.
struct Config {
  double cycle_interval_s = 0.05;      // CYCLEINTERVAL
  double estop_timeout_s = 0.1;        // ESTOPTIMEOUT
  double report_data_timeout_s = 2.0;  // REPORTDATATIMEOUT
  double message_interval_s = 0.5;     // MESSAGEINTERVAL
  double check_interval_s = 1.0;       // CHECKINTERVAL
  std::uint8_t authority_code = 225;   // AUTHORITYCODE

  /// ConfigError::None when every parameter is usable.
  [[nodiscard]] ConfigError validate() const noexcept;

  /// The timers in cycles: max(1, ceil(p / CYCLEINTERVAL - 1e-9)). Only meaningful when
  /// validate() returns None.
  [[nodiscard]] Timing timing() const noexcept;
};

}  // namespace safestate::saf
