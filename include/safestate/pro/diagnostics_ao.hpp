// ao_diagnostics (rank 4, §4): holds the operating status safety publishes, counts the
// events it receives (fault events per cause, lifecycle events, ticks) and publishes the
// process image the communications unit serves.
#pragma once

#include <array>
#include <cstdint>

#include "safestate/pro/active_object.hpp"
#include "safestate/pro/cycle_data.hpp"
#include "safestate/pro/fault_cause.hpp"
#include "safestate/pro/protection_state.hpp"

namespace safestate::pro {

struct DiagnosticCounts {
  std::uint32_t events{0};
  std::uint32_t ticks{0};
  std::uint32_t degraded{0};
  std::uint32_t recoveries{0};
  std::array<std::uint32_t, 7> faults{};  // indexed by FaultCause
};

class DiagnosticsAo final : public ActiveObject {
 public:
  explicit DiagnosticsAo(CycleData& data) noexcept : ActiveObject(AoId::diagnostics), data_(data) {}

  [[nodiscard]] ProtectionState published_state() const noexcept { return published_; }
  [[nodiscard]] bool published_override() const noexcept { return override_; }
  [[nodiscard]] FaultCause last_fault() const noexcept { return last_fault_; }
  [[nodiscard]] const DiagnosticCounts& counts() const noexcept { return counts_; }

 protected:
  void on_event(const AoEvent& e) noexcept override;

 private:
  CycleData& data_;
  ProtectionState published_{ProtectionState::normal};
  bool override_{false};
  FaultCause last_fault_{FaultCause::none};
  DiagnosticCounts counts_{};
};

}  // namespace safestate::pro
