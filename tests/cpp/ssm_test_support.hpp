// SPDX-License-Identifier: Apache-2.0
// Shared helpers of the SystemStateManager tests: a healthy plant and a test rig that
// scripts cycles and commands. Not a test file itself (no test_ prefix).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "safestate/command.hpp"
#include "safestate/config.hpp"
#include "safestate/scan_inputs.hpp"
#include "safestate/sim/bus_master.hpp"
#include "safestate/status_record.hpp"
#include "safestate/system_state_manager.hpp"

namespace ssm_test {

using namespace safestate;  // NOLINT: test code

/// A mid-workspace pose of the UR5 (rad).
inline constexpr JointVector kPose{0.0, -1.2, 1.1, -1.4, -1.57, 0.0};
/// Joint 1 turning slowly: MOVING (checked by RSM10 tests).
inline constexpr JointVector kSlow{0.05, 0.0, 0.0, 0.0, 0.0, 0.0};
/// Joint 1 turning fast: OVER_T1 (well above 250 mm/s at this pose).
inline constexpr JointVector kFast{2.0, 0.0, 0.0, 0.0, 0.0, 0.0};
/// Joint 1 at half kFast: ~640 mm/s at the flange, between the T1 and the T2 limit (OVER_T1).
inline constexpr JointVector kMedium{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
inline constexpr JointVector kRest{};

/// The design-page defaults with the tool stated as a tool-less flange: a Config states its
/// tool (design §9), and these tests measure the speed at the flange.
inline Config flange_config() {
  Config c;
  c.tool_offset_m = kFlangeTcp;
  return c;
}

inline SelectorContacts contacts(SelectorReading mode) {
  SelectorContacts c;
  c.auto_ = mode == SelectorReading::Auto;
  c.t1 = mode == SelectorReading::T1;
  c.t2 = mode == SelectorReading::T2;
  return c;  // Invalid: no contact closed
}

/// Everything healthy in `mode`: E-stop released, gate closed, self-test passed, robot at
/// rest (drives and bus: the Rig's `plant`, sim::bus_image); the enabling device in MIDDLE in T1/T2 (the operator
/// holds it) and RELEASED in AUTO.
inline ScanInputs healthy(SelectorReading mode = SelectorReading::Auto) {
  ScanInputs in;
  in.estop_closed = {true, true};
  in.safeguard_closed = {true, true};
  const bool manual = mode == SelectorReading::T1 || mode == SelectorReading::T2;
  const EnablePosition e = manual ? EnablePosition::Middle : EnablePosition::Released;
  in.enabling = {e, e};
  in.selector = contacts(mode);
  in.self_test_ok = true;
  in.operator_link_ok = true;
  in.q = kPose;
  in.qd = kRest;
  return in;
}

/// The status fields a rejected command must leave alone (RSM-13): all but command_result
/// and last_reject_reason.
inline StatusRecord without_command_fields(StatusRecord s) {
  s.command_result = CommandResult::none();
  s.last_reject_reason = RejectReason::None;
  return s;
}

inline std::string describe(const StatusRecord& s) {
  std::string out;
  out += std::string(to_string(s.state)) + " mode=" + std::string(to_string(s.session_mode)) +
         " sel=" + std::string(to_string(s.selector)) + " stop=" + std::string(to_string(s.stop_category)) +
         " fault=" + std::string(to_string(s.fault_code)) + " result=" + std::string(to_string(s.command_result)) +
         " last_reject=" + std::string(to_string(s.last_reject_reason)) + " cycles=" + std::to_string(s.state_cycles) +
         " q=" + std::to_string(s.queue_length);
  return out;
}

/// A manager plus the inputs it sees every cycle. `in` is edited between cycles.
class Rig {
 public:
  explicit Rig(const Config& config = flange_config()) : m(config) {}

  SystemStateManager m;
  ScanInputs in{healthy(SelectorReading::Auto)};
  /// Drives ready, no fault, bus healthy: each cycle() turns these into the process image
  /// (status words, cycle counter, working counter) the manager decodes itself.
  sim::BusLevels plant{};
  ScanOutputs out{};
  /// The contactor's and the brakes' feedback follow the last outputs (ideal devices, C30);
  /// a test of the feedback monitoring sets it false and drives them itself.
  bool ideal_feedback{true};

  void cycle() {
    in.bus = sim::bus_image(m.fieldbus_watchdog(), plant);
    if (ideal_feedback) {
      in.contactor_feedback_closed = out.contactor_closed;
      in.brake_feedback_released = out.brake_release;
    }
    out = m.cycle(in);
  }
  void cycles(std::uint32_t n) {
    for (std::uint32_t i = 0; i < n; ++i) cycle();
  }
  SubmitResult submit(const Command& c) { return m.submit(c); }
  /// Submits and runs one cycle; returns the command's result.
  CommandResult command(const Command& c) {
    EXPECT_EQ(m.submit(c), SubmitResult::queued);
    cycle();
    return m.status().command_result;
  }
  [[nodiscard]] StateId state() const { return m.state(); }
  [[nodiscard]] StatusRecord st() const { return m.status(); }
  [[nodiscard]] std::string cycle_row() const {
    const auto r = m.last_rows().cycle;
    return r == nullptr ? "-" : std::string(r->id);
  }
  [[nodiscard]] std::string command_row() const {
    const auto r = m.last_rows().command;
    return r == nullptr ? "-" : std::string(r->id);
  }

  /// First cycle with healthy inputs in `mode`: BOOT -> IDLE.
  void boot(SelectorReading mode = SelectorReading::Auto) {
    in = healthy(mode);
    cycle();
    ASSERT_EQ(state(), StateId::Idle);
  }

  /// Boot, Servo-on (with T2 confirmation in T2), and drives ready: AUTO_IDLE / MANUAL_IDLE.
  void to_operational(SelectorReading mode = SelectorReading::Auto) {
    boot(mode);
    if (mode == SelectorReading::T2) {
      ASSERT_EQ(command(Command::t2_confirm()), CommandResult::accepted());
    }
    plant.servo_ready = false;
    ASSERT_EQ(command(Command::servo_on()), CommandResult::accepted());
    ASSERT_EQ(state(), StateId::Arming);
    plant.servo_ready = true;
    cycle();
    ASSERT_EQ(state(), mode == SelectorReading::Auto ? StateId::AutoIdle : StateId::ManualIdle);
  }

  /// AUTO_RUNNING with the robot moving.
  void to_auto_running() {
    to_operational(SelectorReading::Auto);
    ASSERT_EQ(command(Command::start()), CommandResult::accepted());
    ASSERT_EQ(state(), StateId::AutoRunning);
    in.qd = kSlow;
    cycle();
    ASSERT_EQ(state(), StateId::AutoRunning);
  }

  /// MANUAL_JOGGING axis 2, +1, `speed` mm/s, robot moving slowly.
  void to_jogging(SelectorReading mode = SelectorReading::T1, std::int32_t speed = 100) {
    to_operational(mode);
    ASSERT_EQ(command(Command::jog_start(2, 1, speed)), CommandResult::accepted());
    ASSERT_EQ(state(), StateId::ManualJogging);
    in.qd = kSlow;
    cycle();
    ASSERT_EQ(state(), StateId::ManualJogging);
  }

  /// A Cat 2 pause from AUTO_RUNNING, robot at rest: HOLD.
  void to_hold() {
    to_auto_running();
    ASSERT_EQ(command(Command::pause()), CommandResult::accepted());
    ASSERT_EQ(state(), StateId::Stopping);
    in.qd = kRest;
    cycle();
    ASSERT_EQ(state(), StateId::Hold);
  }

  /// E-stop pressed (both channels), then released: ESTOP_RESET_NEEDED.
  void to_reset_needed() {
    boot(SelectorReading::Auto);
    in.estop_closed = {false, false};
    cycle();
    ASSERT_EQ(state(), StateId::EstopActive);
    in.estop_closed = {true, true};
    cycle();
    ASSERT_EQ(state(), StateId::EstopResetNeeded);
  }
};

}  // namespace ssm_test
