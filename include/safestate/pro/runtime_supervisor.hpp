// ao_runtime_supervisor (PRO-05, docs/design/protection.md §6-§9): one tick() per cycle
// reads the units' reports and the fault inputs, fires the first matching row of
// kSupervisorRows, and keeps the controlled-shutdown progress. No heap, no exceptions.
#pragma once

#include <cstdint>

#include "safestate/pro/stop_step.hpp"
#include "safestate/pro/supervisor_inputs.hpp"
#include "safestate/pro/supervisor_state.hpp"
#include "safestate/pro/supervisor_step.hpp"

namespace safestate::pro {

// 5 s of 100 ms ticks (§7).
inline constexpr std::uint32_t kInitTimeoutTicks = 50;

class RuntimeSupervisor {
 public:
  explicit RuntimeSupervisor(std::uint32_t init_timeout_ticks = kInitTimeoutTicks) noexcept
      : init_timeout_ticks_(init_timeout_ticks == 0 ? 1 : init_timeout_ticks) {}

  [[nodiscard]] SupervisorStep tick(const SupervisorInputs& in) noexcept;

  [[nodiscard]] SupervisorState state() const noexcept { return state_; }
  [[nodiscard]] std::uint32_t init_ticks() const noexcept { return init_ticks_; }
  // 0 before the shutdown; 1..8: the step of kStopOrder being waited for.
  [[nodiscard]] std::uint8_t stop_step() const noexcept { return stop_step_; }
  [[nodiscard]] bool outputs_safe() const noexcept { return outputs_safe_; }
  // The step being waited for (valid while stop_step() > 0).
  [[nodiscard]] const StopStep& stop_target() const noexcept {
    return kStopOrder[stop_step_ == 0 ? 0 : stop_step_ - 1U];
  }
  [[nodiscard]] std::uint32_t init_timeout_ticks() const noexcept { return init_timeout_ticks_; }

 private:
  [[nodiscard]] bool holds(SupervisorGuard g, const SupervisorInputs& in) const noexcept;
  void advance_shutdown(const SupervisorInputs& in) noexcept;

  std::uint32_t init_timeout_ticks_;
  SupervisorState state_{SupervisorState::init};
  std::uint32_t init_ticks_{0};
  std::uint8_t stop_step_{0};
  bool outputs_safe_{false};
};

[[nodiscard]] constexpr DispatchMode dispatch_mode(SupervisorState s) noexcept {
  switch (s) {
    case SupervisorState::run: return DispatchMode::all;
    case SupervisorState::degraded:
    case SupervisorState::shutting_down: return DispatchMode::critical_only;
    case SupervisorState::init:
    case SupervisorState::stopped: break;
  }
  return DispatchMode::none;
}

}  // namespace safestate::pro
