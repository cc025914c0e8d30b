// ao_monitoring (rank 1, §2): validates the tick's raw sample into the snapshot safety and
// control read, and attaches a pending latch clear request (consumed once; refused unless
// the supervisor is in RUN: a remote clear is non-critical, §8).
#pragma once

#include "safestate/pro/active_object.hpp"
#include "safestate/pro/cycle_data.hpp"
#include "safestate/pro/sensor_validator.hpp"

namespace safestate::pro {

class MonitoringAo final : public ActiveObject {
 public:
  explicit MonitoringAo(CycleData& data, SensorRange range = {}) noexcept
      : ActiveObject(AoId::monitoring), data_(data), validator_(range) {}
  [[nodiscard]] const SensorValidator& validator() const noexcept { return validator_; }

 protected:
  void on_event(const AoEvent& e) noexcept override;

 private:
  CycleData& data_;
  SensorValidator validator_;
};

}  // namespace safestate::pro
