// SPDX-License-Identifier: Apache-2.0
// The SystemStateManager of a 6-axis industrial robot (RSM-01..RSM-17), implementing
// docs/design/system-state-manager.md row by row.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "safestate/command.hpp"
#include "safestate/command_result.hpp"
#include "safestate/config.hpp"
#include "safestate/derived_inputs.hpp"
#include "safestate/drive_status_summary.hpp"
#include "safestate/dual_channel_input.hpp"
#include "safestate/enable_position.hpp"
#include "safestate/feedback_monitor.hpp"
#include "safestate/fieldbus_watchdog.hpp"
#include "safestate/fired_rows.hpp"
#include "safestate/machine_state.hpp"
#include "safestate/mode_selector.hpp"
#include "safestate/plcopen_axis.hpp"
#include "safestate/reset_interlock.hpp"
#include "safestate/scan_inputs.hpp"
#include "safestate/scan_outputs.hpp"
#include "safestate/speed_monitor.hpp"
#include "safestate/spsc_queue.hpp"
#include "safestate/status_record.hpp"
#include "safestate/submit_result.hpp"
#include "safestate/transition_row.hpp"

namespace safestate {

/// Threading: one producer thread may call submit() while the control thread calls cycle();
/// every other member is for the control thread (or for a quiescent manager). Nothing here
/// allocates after construction, throws, or blocks; a cycle does bounded work (at most one
/// command, 64 table rows, one Jacobian).
class SystemStateManager {
 public:
  using CommandQueue = SpscQueue<Command, kMaxQueueCapacity>;

  /// Starts in BOOT (§7: counters 0, selector INVALID, outputs off, axes Disabled). An invalid
  /// Config is not refused here: the first cycle's self-test fails instead (C02).
  explicit SystemStateManager(const Config& config = Config{}) noexcept;

  SystemStateManager(const SystemStateManager&) = delete;
  SystemStateManager& operator=(const SystemStateManager&) = delete;
  SystemStateManager(SystemStateManager&&) = delete;
  SystemStateManager& operator=(SystemStateManager&&) = delete;
  ~SystemStateManager() = default;

  /// Producer side (§1, RSM-14): queues the command, or rejects it at once when
  /// `command_queue_limit` commands are waiting (last_reject_reason := QUEUE_FULL).
  [[nodiscard]] SubmitResult submit(const Command& command) noexcept;

  /// One scan cycle: §3 channel monitoring, one §5 row, at most one command (§6), then the
  /// §7 outputs and one §8 step of every axis.
  [[nodiscard]] ScanOutputs cycle(const ScanInputs& inputs) noexcept;

  /// §7 status record of the current state (after the last cycle or submit).
  [[nodiscard]] StatusRecord status() const noexcept;
  /// §7 outputs of the current state (what the last cycle returned).
  [[nodiscard]] ScanOutputs outputs() const noexcept;
  /// The rows that fired in the last cycle.
  [[nodiscard]] FiredRows last_rows() const noexcept { return last_rows_; }

  [[nodiscard]] StateId state() const noexcept { return state_id(state_); }
  [[nodiscard]] const MachineState& machine_state() const noexcept { return state_; }
  /// The abstract inputs the last cycle derived (§2); the safe defaults before the first.
  [[nodiscard]] const DerivedInputs& derived_inputs() const noexcept { return derived_; }
  [[nodiscard]] const std::array<PlcopenAxis, kAxisCount>& axes() const noexcept { return axes_; }
  [[nodiscard]] const Config& config() const noexcept { return config_; }
  [[nodiscard]] ConfigError config_error() const noexcept { return config_error_; }
  [[nodiscard]] const SpeedMonitor& speed_monitor() const noexcept { return speed_; }
  [[nodiscard]] std::size_t queue_length() const noexcept { return queue_.size(); }
  /// The fieldbus watchdog after the last cycle (§2, C24).
  [[nodiscard]] const FieldbusWatchdog& fieldbus_watchdog() const noexcept { return fieldbus_; }
  /// The drives' decoded status words of the last cycle (§2).
  [[nodiscard]] const DriveStatusSummary& drive_status() const noexcept { return drives_; }

 private:
  void derive_inputs(const ScanInputs& in) noexcept;
  void fire(const TransitionRow& row, StepContext& ctx, bool is_command) noexcept;
  void step_axes() noexcept;

  Config config_;
  ConfigError config_error_;
  std::size_t queue_limit_;
  SpeedMonitor speed_;

  DualChannelInput<bool> estop_;
  DualChannelInput<bool> safeguard_;
  DualChannelInput<EnablePosition> enabling_;
  ModeSelector selector_;
  FieldbusWatchdog fieldbus_;
  FeedbackMonitor contactor_fb_;  ///< C30: the contactor's auxiliary contact
  FeedbackMonitor brake_fb_;      ///< C30: the brakes' release feedback
  DriveStatusSummary drives_{};

  MachineState state_{states::Boot{}};
  DerivedInputs derived_{};
  StopCategory stop_category_{StopCategory::None};
  ResetInterlock reset_{};
  bool enable_release_required_{false};  ///< K39: PANIC seen since the last RELEASED (both channels)
  CommandResult command_result_{};
  // Written by submit() (producer) and cycle() (consumer): atomic, and a plain value.
  std::atomic<RejectReason> last_reject_reason_{RejectReason::None};
  std::array<PlcopenAxis, kAxisCount> axes_{};
  FiredRows last_rows_{};

  CommandQueue queue_;
};

/// The axis state §8 asks for in manager state `s`, for axis index 0..5.
[[nodiscard]] AxisState desired_axis_state(const MachineState& s, std::size_t axis_index) noexcept;

}  // namespace safestate
