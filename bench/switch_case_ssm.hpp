// SPDX-License-Identifier: Apache-2.0
// Benchmark baseline: the SystemStateManager of docs/design/system-state-manager.md written
// as one flat switch/if-else function, with no transition table and no std::variant.
//
// This is *not* the product implementation. It exists only in bench/ to answer "what does
// the table-driven, variant-based design cost compared with the obvious hand-written
// state machine?" (bench/run_bench.py), and as an independent second implementation that
// bench_cycle's cross-check mode runs in lockstep with the real one. It reuses the
// library's value types (ScanInputs, Command, Config, ScanOutputs, StatusRecord, the SPSC
// queue, the kinematics and the PLCopen step function), so both do the same arithmetic
// and only the state-machine machinery differs.
#pragma once

#include <array>
#include <cstdint>

#include "safestate/arm_kinematics.hpp"
#include "safestate/command.hpp"
#include "safestate/config.hpp"
#include "safestate/drive_status_summary.hpp"
#include "safestate/feedback_monitor.hpp"
#include "safestate/fieldbus_watchdog.hpp"
#include "safestate/plcopen_axis.hpp"
#include "safestate/scan_inputs.hpp"
#include "safestate/scan_outputs.hpp"
#include "safestate/speed_level.hpp"
#include "safestate/spsc_queue.hpp"
#include "safestate/status_record.hpp"
#include "safestate/submit_result.hpp"

namespace safestate_bench {

class SwitchCaseSsm {
 public:
  explicit SwitchCaseSsm(const safestate::Config& config) noexcept;

  [[nodiscard]] safestate::SubmitResult submit(const safestate::Command& command) noexcept;
  const safestate::ScanOutputs& cycle(const safestate::ScanInputs& in) noexcept;
  [[nodiscard]] const safestate::StatusRecord& status() const noexcept { return status_; }
  [[nodiscard]] const safestate::ScanOutputs& outputs() const noexcept { return out_; }

 private:
  void enter(safestate::StateId s) noexcept;
  void lockout(safestate::FaultCode code) noexcept;
  void stop(safestate::StopCategory cat) noexcept;
  void reject(safestate::RejectReason r) noexcept;
  void pause() noexcept;
  void handle_command(const safestate::Command& c, safestate::SelectorReading sel, bool gate_open, bool enable_middle,
                      bool drive_fault, safestate::StateId state_at_start) noexcept;

  safestate::Config config_;
  safestate::ArmKinematics kin_;
  bool config_ok_;
  safestate::SpscQueue<safestate::Command, safestate::kMaxQueueCapacity> queue_;
  safestate::FieldbusWatchdog bus_;
  safestate::FeedbackMonitor contactor_fb_;  // C30
  safestate::FeedbackMonitor brake_fb_;      // C30

  // Machine state (flat, all fields always present).
  safestate::StateId state_{safestate::StateId::Boot};
  safestate::OperatingMode session_{safestate::OperatingMode::None};
  bool t2_confirmed_{false};
  std::uint32_t state_cycles_{0};
  safestate::StopCategory stopping_cat_{safestate::StopCategory::None};  // CAT1/CAT2 in STOPPING
  safestate::ResumeTarget resume_to_{safestate::ResumeTarget::None};
  std::int32_t jog_axis_{0};
  std::int32_t jog_dir_{0};
  std::int32_t jog_speed_{0};
  safestate::FaultCode fault_{safestate::FaultCode::None};
  std::uint32_t estop_mm_{0};
  std::uint32_t guard_mm_{0};
  std::uint32_t enable_mm_{0};
  std::uint32_t sel_inv_{0};
  std::uint32_t stale_commands_{0};  // K36: commands queued at the E-stop release (C07)
  bool estop_tested_a_{false};       // K37: channel A seen open since the last accepted Reset
  bool estop_tested_b_{false};
  bool enable_release_required_{false};  // K39: PANIC seen since the last RELEASED
  std::array<safestate::PlcopenAxis, safestate::kAxisCount> axes_{};

  safestate::StatusRecord status_{};
  safestate::ScanOutputs out_{};
};

}  // namespace safestate_bench
