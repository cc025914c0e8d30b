// ao_safety as an active object (rank 3, §4): evaluates monitoring's snapshot with
// sm_protection (AoSafety), owns the output gate, and posts IF_OperatingStatus every tick
// and IF_FaultEvent on P01/P03 to diagnostics.
#pragma once

#include "safestate/pro/active_object.hpp"
#include "safestate/pro/ao_safety.hpp"
#include "safestate/pro/cycle_data.hpp"

namespace safestate::pro {

class SafetyAo final : public ActiveObject {
 public:
  SafetyAo(CycleData& data, ActiveObject& diagnostics, ProtectionLimits limits = {}) noexcept
      : ActiveObject(AoId::safety), data_(data), diagnostics_(diagnostics), safety_(limits) {}
  [[nodiscard]] const AoSafety& safety() const noexcept { return safety_; }
  // Posts to diagnostics that were not accepted (queue full or diagnostics stopped).
  [[nodiscard]] std::uint32_t unpublished() const noexcept { return unpublished_; }

 protected:
  void on_event(const AoEvent& e) noexcept override;

 private:
  void publish(const AoEvent& e) noexcept;

  CycleData& data_;
  ActiveObject& diagnostics_;
  AoSafety safety_;
  std::uint32_t unpublished_{0};
};

}  // namespace safestate::pro
