// SPDX-License-Identifier: Apache-2.0
// safestate_demo: a scripted cell scenario through the SystemStateManager, one line per cycle
// in which something happens or changes:
//
//   boot with the E-stop pressed, release, Reset; T1 servo-on, a jog requested too fast
//   (clamped to 250 mm/s), enabling device released (Cat 1); AUTO servo-on, Start, gate
//   opened (Cat 1); Start again, Pause (Cat 2, HOLD), Resume; finally an E-stop channel
//   sticks open: E-stop at once, ERROR_LOCKOUT when the discrepancy time has run out.
//
// A tiny plant closes the loop (sim/cell_plant.hpp, shared with the operator panel).
#include <array>
#include <cstdint>
#include <cstdio>
#include <string>

#include "safestate/command.hpp"
#include "safestate/config.hpp"
#include "safestate/sim/cell_plant.hpp"
#include "safestate/system_state_manager.hpp"
#include "safestate/transition_row.hpp"

namespace {

using namespace safestate;  // NOLINT

using Plant = sim::CellPlant;

struct Snapshot {
  StatusRecord status;
  ScanOutputs outputs;
};

bool changed(const Snapshot& a, const Snapshot& b) {
  return a.outputs != b.outputs || a.status.state != b.status.state ||
         a.status.stop_category != b.status.stop_category || a.status.fault_code != b.status.fault_code ||
         a.status.selector != b.status.selector || b.status.command_result != CommandResult::none();
}

const char* short_axis(AxisState s) {
  switch (s) {
    case AxisState::Disabled: return "Dis";
    case AxisState::StandStill: return "SS";
    case AxisState::Homing: return "Hom";
    case AxisState::DiscreteMotion: return "DM";
    case AxisState::ContinuousMotion: return "CM";
    case AxisState::SynchronizedMotion: return "Syn";
    case AxisState::Stopping: return "Stp";
    case AxisState::ErrorStop: return "Err";
  }
  return "?";
}

std::string outputs_text(const ScanOutputs& o) {
  std::string s;
  s += o.contactor_closed ? "PWR " : "--- ";
  s += o.ramp_down_request ? "RAMP " : "---- ";
  s += o.reset_lamp ? "LAMP " : "---- ";
  char speed[24];
  std::snprintf(speed, sizeof speed, "%3d mm/s ", static_cast<int>(o.commanded_speed_mm_s));
  s += speed;
  s += "axes=";
  for (std::size_t i = 0; i < o.axes.size(); ++i) {
    s += short_axis(o.axes[i]);
    if (i + 1 < o.axes.size()) s += ',';
  }
  return s;
}

std::string reason_text(const StatusRecord& st, const FiredRows& rows) {
  std::string s = "row ";
  s += rows.cycle != nullptr ? std::string(rows.cycle->id) : "-";
  if (rows.command != nullptr) {
    s += "+";
    s += rows.command->id;
    s += " cmd=";
    s += to_string(st.command_result);
  }
  if (st.stop_category != StopCategory::None) {
    s += " stop=";
    s += to_string(st.stop_category);
  }
  if (st.fault_code != FaultCode::None) {
    s += " fault=";
    s += to_string(st.fault_code);
  }
  return s;
}

}  // namespace

int main() {
  const Config config = sim::demo_cell_config();  // 1 ms cycles, 50-cycle discrepancy time
  SystemStateManager manager(config);
  Plant plant;

  std::printf("safestate demo: SystemStateManager, %u us cycles, discrepancy %u cycles, T1 limit %d mm/s\n",
              config.cycle_time_us, config.discrepancy_cycles, static_cast<int>(config.t1_speed_limit_mm_s));
  std::printf("%5s  %-38s %-19s %-5s %-44s %s\n", "cycle", "event", "state", "mode", "outputs", "rows / reason");

  Snapshot last{manager.status(), manager.outputs()};
  ScanOutputs out = manager.outputs();

  // What happens at which cycle: (cycle, event text, action). Listed in time order.
  struct Step {
    std::uint32_t cycle;
    const char* event;
    void (*apply)(Plant&, SystemStateManager&);
  };
  // clang-format off
  static const Step script[] = {
      {1, "power on, E-stop pressed", [](Plant& p, SystemStateManager&) { p.inputs().estop_closed = {false, false}; }},
      {6, "E-stop released", [](Plant& p, SystemStateManager&) { p.inputs().estop_closed = {true, true}; }},
      {10, "operator: RESET", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::reset()); }},
      {14, "selector T1, enabling MIDDLE", [](Plant& p, SystemStateManager&) {
         p.select(SelectorReading::T1);
         p.enabling(EnablePosition::Middle);
       }},
      {16, "operator: SERVO_ON", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::servo_on()); }},
      {24, "operator: JOG_START axis 2 + 600 mm/s", [](Plant&, SystemStateManager& m) {
         (void)m.submit(Command::jog_start(2, 1, 600));
       }},
      {60, "enabling device released", [](Plant& p, SystemStateManager&) { p.enabling(EnablePosition::Released); }},
      {90, "selector AUTO", [](Plant& p, SystemStateManager&) { p.select(SelectorReading::Auto); }},
      {92, "operator: SERVO_ON", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::servo_on()); }},
      {100, "operator: START", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::start()); }},
      {130, "safety gate opened", [](Plant& p, SystemStateManager&) { p.inputs().safeguard_closed = {false, false}; }},
      {150, "safety gate closed", [](Plant& p, SystemStateManager&) { p.inputs().safeguard_closed = {true, true}; }},
      {152, "operator: SERVO_ON", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::servo_on()); }},
      {160, "operator: START", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::start()); }},
      {180, "operator: PAUSE", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::pause()); }},
      {200, "operator: RESUME", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::resume()); }},
      {220, "E-stop channel B stuck open", [](Plant& p, SystemStateManager&) { p.inputs().estop_closed.b = false; }},
      {280, "operator: RESET", [](Plant&, SystemStateManager& m) { (void)m.submit(Command::reset()); }},
  };
  // clang-format on

  std::size_t next = 0;
  constexpr std::uint32_t kLastCycle = 290;
  for (std::uint32_t cycle = 1; cycle <= kLastCycle; ++cycle) {
    std::string event;
    while (next < sizeof script / sizeof script[0] && script[next].cycle == cycle) {
      script[next].apply(plant, manager);
      if (!event.empty()) event += "; ";
      event += script[next].event;
      ++next;
    }
    plant.inputs().bus = sim::bus_image(manager.fieldbus_watchdog(), plant.bus_levels());  // the drives' frame
    out = manager.cycle(plant.inputs());
    const Snapshot now{manager.status(), out};
    if (!event.empty() || changed(last, now)) {
      std::printf("%5u  %-38s %-19s %-5s %-44s %s\n", cycle, event.c_str(),
                  std::string(to_string(now.status.state)).c_str(),
                  std::string(to_string(now.status.session_mode)).c_str(), outputs_text(out).c_str(),
                  reason_text(now.status, manager.last_rows()).c_str());
    }
    last = now;
    plant.react(out, manager.state(), jog(manager.machine_state()));
  }

  const StatusRecord final_status = manager.status();
  std::printf("final: %s, fault %s, last reject %s\n", std::string(to_string(final_status.state)).c_str(),
              std::string(to_string(final_status.fault_code)).c_str(),
              std::string(to_string(final_status.last_reject_reason)).c_str());
  // The scenario is a self-check too: it must end locked out by the stuck E-stop channel.
  return final_status.state == StateId::ErrorLockout && final_status.fault_code == FaultCode::DiscrepancyEstop ? 0 : 1;
}
