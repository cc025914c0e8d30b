// The fan controller's runtime (PRO-01..05, docs/design/protection.md §1, §7-§9): the tick
// source, the supervisor, the dispatcher and the five active objects, wired as the page
// says. One tick(): the units' reports, the supervisor's row, the dispatch cycle in the
// fixed order (each AO run to completion), then the lifecycle events the row sent
// (delivered to every unit, dispatched or not). No heap after construction.
#pragma once

#include <cstdint>

#include "safestate/pro/comms_ao.hpp"
#include "safestate/pro/communications_unit.hpp"
#include "safestate/pro/control_ao.hpp"
#include "safestate/pro/controller_inputs.hpp"
#include "safestate/pro/cycle_data.hpp"
#include "safestate/pro/diagnostics_ao.hpp"
#include "safestate/pro/monitoring_ao.hpp"
#include "safestate/pro/runtime_supervisor.hpp"
#include "safestate/pro/safety_ao.hpp"
#include "safestate/pro/tick_report.hpp"
#include "safestate/pro/tick_source.hpp"

namespace safestate::pro {

struct RuntimeConfig {
  ProtectionLimits limits{};
  SensorRange sensor{};
  FanTuning tuning{};
  std::uint32_t init_timeout_ticks{kInitTimeoutTicks};
};

class ProtectionRuntime {
 public:
  explicit ProtectionRuntime(CommunicationsUnit& comms, RuntimeConfig config = {}) noexcept;
  ProtectionRuntime(const ProtectionRuntime&) = delete;
  ProtectionRuntime& operator=(const ProtectionRuntime&) = delete;

  [[nodiscard]] TickReport tick(const ControllerInputs& in) noexcept;
  // The operator's controlled-shutdown request, taken by the next tick (X01).
  void request_shutdown() noexcept { shutdown_requested_ = true; }

  [[nodiscard]] const RuntimeSupervisor& supervisor() const noexcept { return supervisor_; }
  [[nodiscard]] const CycleData& data() const noexcept { return data_; }
  [[nodiscard]] const AoSafety& safety() const noexcept { return safety_.safety(); }
  [[nodiscard]] const DiagnosticsAo& diagnostics() const noexcept { return diagnostics_; }
  [[nodiscard]] UnitStatus status(UnitId u) const noexcept;
  // Events lost to a full queue or posted to a stopped AO, over every AO (reported,
  // never silent).
  [[nodiscard]] std::uint32_t overflow_count() const noexcept;

 private:
  [[nodiscard]] ActiveObject& ao(AoId id) noexcept;
  void deliver_lifecycle(const SupervisorStep& step) noexcept;
  void post_counted(ActiveObject& target, const AoEvent& e) noexcept;

  CycleData data_{};
  TickSource timer_{};
  UnitStatus dispatcher_status_{UnitStatus::init};
  RuntimeSupervisor supervisor_;
  DiagnosticsAo diagnostics_;
  MonitoringAo monitoring_;
  ControlAo control_;
  SafetyAo safety_;
  CommsAo comms_;
  bool shutdown_requested_{false};
  std::uint32_t dispatcher_resets_{0};
  std::uint32_t lost_lifecycle_{0};
};

}  // namespace safestate::pro
