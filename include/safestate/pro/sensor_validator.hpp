// The monitoring unit's sensor validator (§2): a raw sample is valid when the front end
// does not flag it, both values lie in the sensor's physical range, neither moved more
// than the plausible slew since the previous sample, and the frame counter advanced
// within kStuckTicks ticks (a frozen counter is a stuck front end).
#pragma once

#include <cstdint>

#include "safestate/pro/raw_sample.hpp"
#include "safestate/pro/sensor_snapshot.hpp"
#include "safestate/pro/sensor_verdict.hpp"

namespace safestate::pro {

struct SensorRange {
  std::int16_t temp_min_c{-40};
  std::int16_t temp_max_c{150};
  std::uint16_t volt_max_dv{600};
  std::uint16_t temp_slew_c{20};    // per tick
  std::uint16_t volt_slew_dv{100};  // per tick
  std::uint8_t stuck_ticks{3};      // ticks the frame counter may stay frozen
};

class SensorValidator {
 public:
  explicit SensorValidator(SensorRange range = {}) noexcept : range_(range) {}

  // The verdict on `s` (updates the slew and stuck history).
  [[nodiscard]] SensorVerdict validate(const RawSample& s) noexcept;
  // The snapshot of `s` with its verdict (no clear request).
  [[nodiscard]] SensorSnapshot snapshot(const RawSample& s) noexcept;
  [[nodiscard]] SensorVerdict last_verdict() const noexcept { return last_; }

 private:
  SensorRange range_;
  RawSample previous_{};
  bool has_previous_{false};
  std::uint8_t frozen_ticks_{0};
  SensorVerdict last_{SensorVerdict::ok};
};

}  // namespace safestate::pro
