// SPDX-License-Identifier: Apache-2.0
#include "safestate/link/control_loop.hpp"

#include <thread>

#include "safestate/transition_table.hpp"

namespace safestate::link {

double CycleTimeHistogram::percentile_us(double fraction) const noexcept {
  if (count_ == 0) return 0.0;
  const auto rank = static_cast<std::uint64_t>(fraction * static_cast<double>(count_));
  std::uint64_t seen = 0;
  for (std::size_t us = 0; us < kBuckets; ++us) {  // us: tenths of a microsecond
    seen += buckets_[us];
    if (seen > rank) return static_cast<double>(us + 1) / 10.0;
  }
  return static_cast<double>(kBuckets) / 10.0;
}

ControlLoop::ControlLoop(const Config& config) noexcept : manager_(config) {}

namespace {

std::int16_t row_index_of(const TransitionRow* row) noexcept {
  if (row == nullptr) return -1;
  return static_cast<std::int16_t>(row - kTransitionTable.data());
}

// The simulated devices as the panel set them: both channels of each device follow its
// switch, except an E-stop channel B stuck open.
void apply_switches(sim::CellPlant& plant, const PlantSwitches& s) noexcept {
  ScanInputs& in = plant.inputs();
  in.estop_closed = {!s.estop_pressed, !s.estop_pressed && !s.estop_b_stuck_open};
  in.safeguard_closed = {!s.gate_open, !s.gate_open};
  plant.enabling(s.enabling);
  plant.select(s.selector);
  plant.bus_levels().drive_fault = s.drive_fault;
}

}  // namespace

void ControlLoop::run_one_cycle() noexcept {
  const std::uint32_t word = plant_word_.load(std::memory_order_acquire);
  apply_switches(plant_, PlantSwitches::unpack(word));
  const bool link_ok = heartbeat_.sample();
  plant_.inputs().operator_link_ok = link_ok;
  const StateId before = manager_.state();
  plant_.inputs().bus = sim::bus_image(manager_.fieldbus_watchdog(), plant_.bus_levels());
  const ScanOutputs out = manager_.cycle(plant_.inputs());
  plant_.react(out, manager_.state(), jog(manager_.machine_state()));

  snapshot_.status = manager_.status();
  if (snapshot_.status.command_result != CommandResult::none()) {
    ++snapshot_.commands_popped;
    if (!outcomes_.try_push(CommandOutcome{snapshot_.commands_popped, snapshot_.status.command_result})) {
      outcomes_dropped_.fetch_add(1, std::memory_order_relaxed);  // the bridge reports it lost
    }
  }
  ++snapshot_.cycle;
  snapshot_.outputs = out;
  snapshot_.cycle_row = row_index_of(manager_.last_rows().cycle);
  snapshot_.command_row = row_index_of(manager_.last_rows().command);
  if (manager_.state() != before) {  // an accepted command's row, else the §5 row, moved the state
    const bool by_command = snapshot_.command_row >= 0 && snapshot_.status.command_result == CommandResult::accepted();
    snapshot_.last_transition_row = by_command ? snapshot_.command_row : snapshot_.cycle_row;
    snapshot_.last_transition_from = before;
    snapshot_.recent[snapshot_.recent_next] =
        CellStatus::Transition{snapshot_.cycle + 1, snapshot_.last_transition_row, before, manager_.state()};
    snapshot_.recent_next = static_cast<std::uint8_t>((snapshot_.recent_next + 1U) % snapshot_.recent.size());
  }
  snapshot_.plant_switches = word;
  snapshot_.operator_link_ok = link_ok;
  snapshot_.heartbeat_age_cycles = heartbeat_.age_cycles();
  status_.write(snapshot_);
  cycles_.store(snapshot_.cycle, std::memory_order_release);
}

void ControlLoop::run(const std::atomic<bool>& stop, std::chrono::microseconds period) noexcept {
  using Clock = std::chrono::steady_clock;
  auto next = Clock::now();
  while (!stop.load(std::memory_order_acquire)) {
    if (clear_times_.exchange(false, std::memory_order_acq_rel)) times_.clear();
    const auto start = Clock::now();
    run_one_cycle();
    const auto took = Clock::now() - start;
    times_.add(static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(took).count()));
    next += period;
    const auto now = Clock::now();
    if (next < now) next = now;  // an overrun: no burst of catch-up cycles
    std::this_thread::sleep_until(next);
  }
}

}  // namespace safestate::link
