// ao_control (rank 2, §4, §9): the fan speed controller on the validated temperature. It
// reports FAILED while the fan driver signals a fault (and READY again when it clears);
// on shutdown step 1 it drives the output to the safe value and reports outputs safe.
#pragma once

#include <cstdint>

#include "safestate/pro/active_object.hpp"
#include "safestate/pro/cycle_data.hpp"
#include "safestate/pro/fan_speed_controller.hpp"

namespace safestate::pro {

class ControlAo final : public ActiveObject {
 public:
  explicit ControlAo(CycleData& data, FanTuning tuning = {}) noexcept
      : ActiveObject(AoId::control), data_(data), pid_(tuning) {}

  // The unit's report at the start of a tick: the fan driver's fault line.
  void report_driver(bool fault) noexcept;
  [[nodiscard]] bool outputs_safe() const noexcept { return outputs_safe_; }
  [[nodiscard]] std::uint32_t degraded_count() const noexcept { return degraded_; }

 protected:
  void on_event(const AoEvent& e) noexcept override;

 private:
  CycleData& data_;
  FanSpeedController pid_;
  bool outputs_safe_{false};
  std::uint32_t degraded_{0};
};

}  // namespace safestate::pro
