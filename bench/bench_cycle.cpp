// SPDX-License-Identifier: Apache-2.0
// Replays a long, seeded, random but realistic scenario through one SystemStateManager
// implementation, for bench/run_bench.py (instruction counts under callgrind) and as a
// lockstep cross-check of the two implementations.
//
//   bench_cycle ssm|switch [--cycles N] [--seed S] [--per-cycle] [--quiet]
//   bench_cycle crosscheck [--cycles N] [--seed S] [--require-every-state]
//   bench_cycle describe   --seed S --cycle K      (what happened in cycle K, both impls)
//
// Implementations: `ssm` = safestate::SystemStateManager (the product: transition table +
// std::variant), `switch` = safestate_bench::SwitchCaseSsm (flat switch-case baseline).
//
// Measurement hooks. The only code callgrind should count is the implementation's
// cycle() member function: run_bench.py passes --toggle-collect=<that function>, so the
// scenario generator, the plant model and this driver are never counted. With
// --per-cycle the driver additionally issues CALLGRIND_DUMP_STATS_AT("cycle=<k>") after
// every cycle: each dump holds exactly one cycle's cost, which gives the exact
// per-cycle distribution (mean, percentiles, worst case). Outside valgrind the client
// requests are a few no-op instructions.
//
// Heap: global operator new/delete are replaced by counting versions; the program reports
// the allocations made while constructing the implementation and those made afterwards
// (submit + cycle over the whole scenario, including the re-initialisations that follow a
// lockout, which construct the implementation in place without heap).
#include <array>
#include <atomic>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <string_view>

#include "safestate/sim/bus_master.hpp"
#include "safestate/system_state_manager.hpp"
#include "switch_case_ssm.hpp"

#if defined(SAFESTATE_HAVE_CALLGRIND_H)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_DUMP_STATS_AT(x) ((void)(x))
#endif

// ---------------------------------------------------------------------------------------
// Heap allocation counting (whole program).
namespace {
std::atomic<std::uint64_t> g_allocations{0};
std::atomic<std::uint64_t> g_deallocations{0};

void* counted_alloc(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (n == 0) n = 1;
  void* p = std::malloc(n);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
void* counted_alloc_aligned(std::size_t n, std::size_t align) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (n == 0) n = 1;
  const std::size_t rounded = (n + align - 1) / align * align;
  void* p = std::aligned_alloc(align, rounded);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
void counted_free(void* p) noexcept {
  if (p != nullptr) g_deallocations.fetch_add(1, std::memory_order_relaxed);
  std::free(p);
}
}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t n, std::align_val_t a) { return counted_alloc_aligned(n, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t n, std::align_val_t a) {
  return counted_alloc_aligned(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { counted_free(p); }

namespace {

using safestate::Command;
using safestate::CommandKind;
using safestate::Config;
using safestate::EnablePosition;
using safestate::OperatingMode;
using safestate::ScanInputs;
using safestate::ScanOutputs;
using safestate::SelectorReading;
using safestate::StateId;
using safestate::StatusRecord;
using safestate::SubmitResult;

// The design-page defaults with the tool stated (a tool-less flange), as a Config must.
Config bench_config() noexcept {
  Config c;
  c.tool_offset_m = safestate::kFlangeTcp;
  return c;
}

// ---------------------------------------------------------------------------------------
// Deterministic RNG (splitmix64): same seed, same scenario, on every platform.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) noexcept : s_(seed) {}
  std::uint64_t next() noexcept {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// True with probability 1/n.
  bool one_in(std::uint64_t n) noexcept { return next() % n == 0; }
  /// Uniform integer in [lo, hi].
  std::int32_t range(std::int32_t lo, std::int32_t hi) noexcept {
    const auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo + 1);
    return static_cast<std::int32_t>(lo + static_cast<std::int64_t>(next() % span));
  }
  double uniform(double lo, double hi) noexcept {
    return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1.0p-53);
  }

 private:
  std::uint64_t s_;
};

// ---------------------------------------------------------------------------------------
// A dual-channel input whose channel B follows channel A after a short lag (contact
// bounce / different switching times), occasionally longer than the discrepancy time.
struct LaggedPair {
  bool a{true};
  bool b{true};
  std::int32_t lag_left{0};
  void set(bool level, Rng& rng, std::int32_t max_lag, std::uint64_t stuck_one_in) {
    if (level == a) return;
    a = level;
    lag_left = rng.range(0, max_lag);
    if (stuck_one_in != 0 && rng.one_in(stuck_one_in)) lag_left = rng.range(60, 400);  // > D
  }
  void tick() {
    if (a != b) {
      if (lag_left <= 0) {
        b = a;
      } else {
        --lag_left;
      }
    }
  }
};

struct EnablePair {
  EnablePosition a{EnablePosition::Released};
  EnablePosition b{EnablePosition::Released};
  std::int32_t lag_left{0};
  void set(EnablePosition p, Rng& rng) {
    if (p == a) return;
    a = p;
    lag_left = rng.range(0, 4);
    if (rng.one_in(3000)) lag_left = rng.range(60, 200);  // rare: longer than D
  }
  void tick() {
    if (a != b) {
      if (lag_left <= 0) {
        b = a;
      } else {
        --lag_left;
      }
    }
  }
};

// ---------------------------------------------------------------------------------------
// Operator, cell and plant model. It reacts only to the observable status and outputs of
// the implementation, so two implementations that agree see exactly the same inputs.
class Scenario {
 public:
  explicit Scenario(std::uint64_t seed) noexcept : rng_(seed) { power_on(); }

  /// Called when the controller is re-initialised (power cycle).
  void power_on() noexcept {
    self_test_ok_ = !rng_.one_in(40);
    drive_fault_ = false;
    arming_cycles_ = 0;
    ready_delay_ = 0;
    stuck_stop_ = false;
    qd_.fill(0.0);
  }

  /// Inputs of the next cycle, given the status and outputs after the previous cycle.
  const ScanInputs& next_inputs(const StatusRecord& st, const ScanOutputs& out) noexcept {
    world_events(st);
    estop_.tick();
    guard_.tick();
    enabling_.tick();
    if (selector_transition_ > 0) --selector_transition_;
    plant(st, out);
    // The contactor's and the brakes' feedback follow their command (C30).
    in_.contactor_feedback_closed = out.contactor_closed;
    in_.brake_feedback_released = out.brake_release;

    in_.estop_closed.a = estop_.a;
    in_.estop_closed.b = estop_.b;
    in_.safeguard_closed.a = guard_.a;
    in_.safeguard_closed.b = guard_.b;
    in_.enabling.a = enabling_.a;
    in_.enabling.b = enabling_.b;
    const SelectorReading shown = selector_transition_ > 0 ? SelectorReading::Invalid : selector_;
    in_.selector.auto_ = shown == SelectorReading::Auto;
    in_.selector.t1 = shown == SelectorReading::T1;
    in_.selector.t2 = shown == SelectorReading::T2;
    if (selector_transition_ > 0 && selector_both_) {  // make-before-break: two contacts
      in_.selector.auto_ = true;
      in_.selector.t1 = true;
    }
    in_.self_test_ok = self_test_ok_;
    // Drives and bus through a simulated EtherCAT master: both implementations decode the
    // same status words and supervise the same frame counter. Ready after the drives' delay
    // in ARMING, and kept while powered but for a rare loss (C27).
    const bool ready_kept = safestate::is_powered(st.state) && st.state != StateId::Arming && !rng_.one_in(20'000);
    in_.bus = master_.next(safestate::sim::BusLevels{
        fieldbus_ok_, (st.state == StateId::Arming && arming_cycles_ >= ready_delay_) || ready_kept, drive_fault_});
    in_.operator_link_ok = link_lost_cycles_ == 0;
    in_.q = q_;
    in_.qd = qd_;
    return in_;
  }

  /// Operator-interface commands for this cycle (0, 1 or a burst). Returns how many.
  int commands(const StatusRecord& st, std::array<Command, 24>& buf) noexcept {
    int n = 0;
    if (rng_.one_in(25'000)) {  // a burst that overflows the queue (RSM-14)
      const int burst = rng_.range(10, 20);
      for (int i = 0; i < burst; ++i) buf[static_cast<std::size_t>(n++)] = random_command();
      return n;
    }
    if (!rng_.one_in(120)) return 0;
    if (rng_.one_in(8)) {
      buf[static_cast<std::size_t>(n++)] = random_command();
      return n;
    }
    switch (st.state) {
      case StateId::EstopResetNeeded: buf[static_cast<std::size_t>(n++)] = Command::reset(); break;
      case StateId::Idle:
        if (st.selector == SelectorReading::T2 && !st.t2_confirmed) {
          buf[static_cast<std::size_t>(n++)] = Command::t2_confirm();
        } else {
          buf[static_cast<std::size_t>(n++)] = Command::servo_on();
        }
        break;
      case StateId::AutoIdle:
        buf[static_cast<std::size_t>(n++)] = rng_.one_in(15) ? Command::servo_off() : Command::start();
        break;
      case StateId::AutoRunning:
        if (rng_.one_in(6)) {
          buf[static_cast<std::size_t>(n++)] = rng_.one_in(2) ? Command::pause() : Command::servo_off();
        }
        break;
      case StateId::Hold:
        buf[static_cast<std::size_t>(n++)] = rng_.one_in(6) ? Command::servo_off() : Command::resume();
        break;
      case StateId::ManualIdle:
        buf[static_cast<std::size_t>(n++)] =
            rng_.one_in(12) ? Command::servo_off()
                            : Command::jog_start(rng_.range(1, 6), rng_.one_in(2) ? 1 : -1, rng_.range(20, 600));
        break;
      case StateId::ManualJogging:
        if (rng_.one_in(3)) {
          buf[static_cast<std::size_t>(n++)] = rng_.one_in(3) ? Command::pause() : Command::jog_stop();
        }
        break;
      default:
        if (rng_.one_in(4)) buf[static_cast<std::size_t>(n++)] = random_command();
        break;
    }
    return n;
  }

 private:
  Command random_command() noexcept {
    const auto kind = static_cast<CommandKind>(rng_.range(0, 8));
    Command c{kind, 0, 0, 0};
    if (kind == CommandKind::JogStart) {
      c.axis = rng_.range(-1, 8);
      c.direction = rng_.range(-2, 2);
      c.speed_mm_s = rng_.range(-50, 900);
    }
    return c;
  }

  void world_events(const StatusRecord& st) noexcept {
    const bool powered = safestate::is_powered(st.state);
    // E-stop: pressed now and then, released after a while.
    if (estop_.a) {
      if (rng_.one_in(15'000)) estop_.set(false, rng_, 8, 150);
    } else if (rng_.one_in(600)) {
      estop_.set(true, rng_, 8, 150);
    }
    // Safeguard: the operator opens the gate now and then (more often when not in AUTO).
    const bool auto_session = st.session_mode == OperatingMode::Auto;
    if (guard_.a) {
      if (rng_.one_in(auto_session ? 40'000 : 4'000)) guard_.set(false, rng_, 5, 400);
    } else if (rng_.one_in(800)) {
      guard_.set(true, rng_, 5, 400);
    }
    // Enabling device: held in the middle by a manual operator, released or panicked.
    const bool manual_intent = selector_ == SelectorReading::T1 || selector_ == SelectorReading::T2;
    if (manual_intent) {
      if (enabling_.a == EnablePosition::Middle) {
        if (rng_.one_in(9'000)) enabling_.set(EnablePosition::Released, rng_);
        if (rng_.one_in(120'000)) enabling_.set(EnablePosition::Panic, rng_);
      } else if (rng_.one_in(300)) {
        enabling_.set(EnablePosition::Middle, rng_);
      }
    } else if (enabling_.a != EnablePosition::Released && rng_.one_in(200)) {
      enabling_.set(EnablePosition::Released, rng_);
    }
    // Mode selector: turned rarely; the contacts pass through an invalid reading.
    // The operator picks the mode before Servo-on far more often than while powered.
    if (selector_transition_ == 0 && rng_.one_in(st.state == StateId::Idle ? 2'500 : 45'000)) {
      const SelectorReading modes[] = {SelectorReading::Auto, SelectorReading::T1, SelectorReading::T2};
      selector_ = modes[rng_.range(0, 2)];
      selector_transition_ = rng_.one_in(400) ? rng_.range(60, 120) : rng_.range(1, 20);
      selector_both_ = rng_.one_in(3);
    }
    // Drives.
    if (st.state == StateId::Arming) {
      if (arming_cycles_ == 0) {
        ready_delay_ = rng_.one_in(80) ? 1'000'000 : rng_.range(0, 300);  // rare: never ready
      }
      ++arming_cycles_;
    } else {
      arming_cycles_ = 0;
    }
    if (powered && rng_.one_in(400'000)) drive_fault_ = true;
    // Fieldbus / cycle watchdog (C24): healthy but for a rare loss (a lockout).
    fieldbus_ok_ = !rng_.one_in(2'000'000);
    // Operator link (C26): the heartbeat lapses now and then for a while, mostly in a jog.
    if (link_lost_cycles_ > 0) {
      --link_lost_cycles_;
    } else if (rng_.one_in(st.state == StateId::ManualJogging ? 3'000 : 60'000)) {
      link_lost_cycles_ = rng_.range(1, 300);
    }
  }

  void plant(const StatusRecord& st, const ScanOutputs& out) noexcept {
    constexpr double dt = 0.001;
    if (!out.brake_release) {
      qd_.fill(0.0);  // brakes engaged
      stuck_stop_ = false;
      return;
    }
    switch (st.state) {
      case StateId::AutoRunning: {
        // A smooth multi-axis path: each joint follows its own slow sinusoid.
        phase_ += dt;
        for (std::size_t i = 0; i < qd_.size(); ++i) {
          const double w = 0.7 + 0.13 * static_cast<double>(i);
          qd_[i] = 0.35 * std::sin(w * phase_ + static_cast<double>(i));
        }
        break;
      }
      case StateId::ManualJogging: {
        // The jog axis ramps to a joint rate matching the commanded TCP speed (~0.8 m lever),
        // the others hold. In T1 a rare sensor glitch / runaway exceeds the limit.
        const std::size_t ax = static_cast<std::size_t>(st.jog_axis >= 1 && st.jog_axis <= 6 ? st.jog_axis - 1 : 0);
        double target =
            static_cast<double>(st.jog_direction) * static_cast<double>(out.commanded_speed_mm_s) / 1000.0 / 0.8;
        if (rng_.one_in(30'000)) target *= 4.0;
        for (std::size_t i = 0; i < qd_.size(); ++i) {
          const double goal = i == ax ? target : 0.0;
          qd_[i] += std::fmax(-0.002, std::fmin(0.002, goal - qd_[i]));
        }
        break;
      }
      case StateId::Stopping: {
        if (st.state_cycles == 0) stuck_stop_ = rng_.one_in(300);  // rare: a drive does not stop
        for (double& v : qd_) {
          if (stuck_stop_) continue;
          const double step = 0.004;
          v = std::fabs(v) <= step ? 0.0 : v - std::copysign(step, v);
        }
        break;
      }
      default: {
        // Holding position: servo noise well below the zero-velocity threshold.
        for (double& v : qd_) v = rng_.uniform(-2e-4, 2e-4);
        break;
      }
    }
    for (std::size_t i = 0; i < q_.size(); ++i) q_[i] += qd_[i] * dt;
  }

  Rng rng_;
  LaggedPair estop_{};
  LaggedPair guard_{};
  EnablePair enabling_{};
  SelectorReading selector_{SelectorReading::T1};
  std::int32_t selector_transition_{0};
  bool selector_both_{false};
  bool self_test_ok_{true};
  bool drive_fault_{false};
  bool fieldbus_ok_{true};
  safestate::sim::BusMaster master_{bench_config().fieldbus_expected_working_counter};
  std::int32_t link_lost_cycles_{0};
  std::int32_t arming_cycles_{0};
  std::int32_t ready_delay_{0};
  bool stuck_stop_{false};
  double phase_{0.0};
  safestate::JointVector q_{0.0, -1.2, 1.1, -1.4, -1.57, 0.0};
  safestate::JointVector qd_{};
  ScanInputs in_{};
};

// ---------------------------------------------------------------------------------------
// Statistics of a run (native, outside the measured function).
struct Stats {
  std::array<std::uint64_t, safestate::kStateCount> state_cycles{};
  std::uint64_t accepted{0};
  std::uint64_t rejected{0};
  std::uint64_t queue_full{0};
  std::uint64_t submitted{0};
  std::uint64_t power_cycles{0};
  std::uint64_t transitions{0};
  std::array<std::uint64_t, safestate::kFaultCodeCount> lockouts{};
};

struct Options {
  std::string_view impl{"ssm"};
  std::uint64_t cycles{200'000};
  std::uint64_t seed{20240611};
  bool per_cycle{false};
  bool quiet{false};
  bool require_every_state{false};  // crosscheck: fail when a state was never reached
  std::uint64_t describe_cycle{0};
  std::uint64_t lockout_reboot_cycles{1000};
};

template <typename Impl>
class Runner {
 public:
  explicit Runner(const Options& opt) : opt_(opt), scenario_(opt.seed) {}

  /// Runs the scenario; returns the number of heap allocations after construction.
  void run() {
    const std::uint64_t before_construct = g_allocations.load();
    impl_.emplace(config_);
    construct_allocs_ = g_allocations.load() - before_construct;
    const std::uint64_t after_construct = g_allocations.load();

    std::array<Command, 24> cmds{};
    StateId prev = impl_->status().state;
    std::uint64_t in_lockout = 0;
    for (std::uint64_t k = 0; k < opt_.cycles; ++k) {
      const int n = scenario_.commands(impl_->status(), cmds);
      for (int i = 0; i < n; ++i) {
        ++stats_.submitted;
        if (impl_->submit(cmds[static_cast<std::size_t>(i)]) == SubmitResult::queue_full) ++stats_.queue_full;
      }
      const ScanInputs& in = scenario_.next_inputs(impl_->status(), last_out_);
      last_out_ = impl_->cycle(in);  // <- the measured call
      if (opt_.per_cycle) CALLGRIND_DUMP_STATS_AT(label(k));
      const StatusRecord& st = impl_->status();
      ++stats_.state_cycles[static_cast<std::size_t>(st.state)];
      if (st.command_result.outcome() == safestate::CommandResult::Outcome::Accepted) ++stats_.accepted;
      if (st.command_result.outcome() == safestate::CommandResult::Outcome::Rejected) ++stats_.rejected;
      if (st.state != prev) {
        ++stats_.transitions;
        if (st.state == StateId::ErrorLockout) ++stats_.lockouts[static_cast<std::size_t>(st.fault_code)];
      }
      prev = st.state;
      in_lockout = st.state == StateId::ErrorLockout ? in_lockout + 1 : 0;
      if (in_lockout == opt_.lockout_reboot_cycles) {  // power cycle: re-initialise in place
        impl_.emplace(config_);
        last_out_ = ScanOutputs{};
        scenario_.power_on();
        prev = impl_->status().state;
        in_lockout = 0;
        ++stats_.power_cycles;
      }
    }
    run_allocs_ = g_allocations.load() - after_construct;
  }

  void print(const char* name) const {
    std::printf("impl=%s cycles=%" PRIu64 " seed=%" PRIu64 "\n", name, opt_.cycles, opt_.seed);
    std::printf("heap_allocations_construction=%" PRIu64 "\n", construct_allocs_);
    std::printf("heap_allocations_after_construction=%" PRIu64 "\n", run_allocs_);
    std::printf("commands_submitted=%" PRIu64 " queue_full=%" PRIu64 " accepted=%" PRIu64 " rejected=%" PRIu64 "\n",
                stats_.submitted, stats_.queue_full, stats_.accepted, stats_.rejected);
    std::printf("state_changes=%" PRIu64 " power_cycles=%" PRIu64 "\n", stats_.transitions, stats_.power_cycles);
    std::printf("lockouts:");
    for (const safestate::FaultCode f : safestate::kAllFaultCodes) {
      if (f == safestate::FaultCode::None) continue;
      std::printf(" %.*s=%" PRIu64, static_cast<int>(safestate::to_string(f).size()), safestate::to_string(f).data(),
                  stats_.lockouts[static_cast<std::size_t>(f)]);
    }
    std::printf("\n");
    std::printf("cycles_per_state:");
    for (const StateId s : safestate::kAllStates) {
      std::printf(" %.*s=%" PRIu64, static_cast<int>(safestate::to_string(s).size()), safestate::to_string(s).data(),
                  stats_.state_cycles[static_cast<std::size_t>(s)]);
    }
    std::printf("\n");
  }

 private:
  const char* label(std::uint64_t k) noexcept {
    std::snprintf(label_, sizeof label_, "cycle=%" PRIu64, k);
    return label_;
  }

  Options opt_;
  Config config_{bench_config()};
  Scenario scenario_;
  std::optional<Impl> impl_;
  ScanOutputs last_out_{};
  Stats stats_{};
  std::uint64_t construct_allocs_{0};
  std::uint64_t run_allocs_{0};
  char label_[48]{};
};

// ---------------------------------------------------------------------------------------
// Lockstep cross-check: both implementations, same inputs, compare after every step.

void print_status(const char* who, const StatusRecord& s, const ScanOutputs& o) {
  auto sv = [](std::string_view v) { return static_cast<int>(v.size()); };
  const auto st = safestate::to_string(s.state);
  const auto sel = safestate::to_string(s.selector);
  const auto mode = safestate::to_string(s.session_mode);
  const auto cat = safestate::to_string(s.stop_category);
  const auto fault = safestate::to_string(s.fault_code);
  const auto rej = safestate::to_string(s.last_reject_reason);
  const auto res = safestate::to_string(s.command_result);
  const auto res_to = safestate::to_string(s.resume_to);
  std::printf(
      "  %-7s state=%.*s selector=%.*s session=%.*s stop=%.*s fault=%.*s last_reject=%.*s "
      "result=%.*s\n          mm(estop,guard,enable,sel)=(%u,%u,%u,%u) state_cycles=%u t2=%d "
      "resume_to=%.*s jog=(%d,%d,%d) queue=%zu\n",
      who, sv(st), st.data(), sv(sel), sel.data(), sv(mode), mode.data(), sv(cat), cat.data(), sv(fault), fault.data(),
      sv(rej), rej.data(), sv(res), res.data(), s.estop_mismatch, s.safeguard_mismatch, s.enabling_mismatch,
      s.selector_invalid, s.state_cycles, s.t2_confirmed ? 1 : 0, sv(res_to), res_to.data(), s.jog_axis,
      s.jog_direction, s.jog_speed_mm_s, s.queue_length);
  std::printf("          out: contactor=%d enable=%d brake=%d ramp=%d lamp=%d speed=%d axes=", o.contactor_closed,
              o.drive_enable, o.brake_release, o.ramp_down_request, o.reset_lamp, o.commanded_speed_mm_s);
  for (const auto a : o.axes) {
    const auto n = safestate::to_string(a);
    std::printf("%.*s ", sv(n), n.data());
  }
  std::printf("\n");
}

void print_inputs(const ScanInputs& in) {
  std::printf(
      "  inputs: estop=(%d,%d) guard=(%d,%d) enabling=(%d,%d) selector(auto,t1,t2)=(%d,%d,%d) "
      "self_test=%d status_word[0]=0x%04x wkc=%u counter=%u\n          qd=[",
      in.estop_closed.a, in.estop_closed.b, in.safeguard_closed.a, in.safeguard_closed.b,
      static_cast<int>(in.enabling.a), static_cast<int>(in.enabling.b), in.selector.auto_, in.selector.t1,
      in.selector.t2, in.self_test_ok, static_cast<unsigned>(in.bus.status_words[0]),
      static_cast<unsigned>(in.bus.working_counter), static_cast<unsigned>(in.bus.cycle_counter));
  for (const double v : in.qd) std::printf(" %.5f", v);
  std::printf(" ]\n");
}

void print_command(const Command& c) {
  const auto k = safestate::to_string(c.kind);
  std::printf("  submit %.*s(%d,%d,%d)\n", static_cast<int>(k.size()), k.data(), c.axis, c.direction, c.speed_mm_s);
}

int crosscheck(const Options& opt, bool describe) {
  const Config config = bench_config();
  std::optional<safestate::SystemStateManager> a;
  std::optional<safestate_bench::SwitchCaseSsm> b;
  a.emplace(config);
  b.emplace(config);
  Scenario scenario(opt.seed);
  ScanOutputs out_a{};
  ScanOutputs out_b{};
  std::array<Command, 24> cmds{};
  std::uint64_t in_lockout = 0;
  std::uint64_t steps = 0;
  std::uint64_t power_cycles = 0;
  std::array<bool, safestate::kStateCount> visited{};  // a run that misses a state proves little
  const std::uint64_t last = describe ? opt.describe_cycle + 1 : opt.cycles;
  for (std::uint64_t k = 0; k < last; ++k) {
    const bool show = describe && k == opt.describe_cycle;
    if (show) {
      std::printf("before cycle %" PRIu64 ":\n", k);
      print_status("ssm", a->status(), out_a);
    }
    const int n = scenario.commands(a->status(), cmds);
    for (int i = 0; i < n; ++i) {
      const Command& c = cmds[static_cast<std::size_t>(i)];
      if (show) print_command(c);
      const SubmitResult ra = a->submit(c);
      const SubmitResult rb = b->submit(c);
      ++steps;
      if (ra != rb || a->status() != b->status()) {
        std::printf("DIVERGENCE at cycle %" PRIu64 " on submit #%d (step %" PRIu64 "): submit -> ssm %s, switch %s\n",
                    k, i, steps, ra == SubmitResult::queued ? "queued" : "queue_full",
                    rb == SubmitResult::queued ? "queued" : "queue_full");
        print_command(c);
        print_status("ssm", a->status(), out_a);
        print_status("switch", b->status(), out_b);
        return 1;
      }
    }
    const ScanInputs in = scenario.next_inputs(a->status(), out_a);
    if (show) print_inputs(in);
    out_a = a->cycle(in);
    out_b = b->cycle(in);
    ++steps;
    if (show) {
      std::printf("after cycle %" PRIu64 ":\n", k);
      print_status("ssm", a->status(), out_a);
      print_status("switch", b->status(), out_b);
    }
    if (out_a != out_b || a->status() != b->status()) {
      std::printf("DIVERGENCE at cycle %" PRIu64 " (step %" PRIu64 ")\n", k, steps);
      print_inputs(in);
      print_status("ssm", a->status(), out_a);
      print_status("switch", b->status(), out_b);
      return 1;
    }
    visited[static_cast<std::size_t>(a->status().state)] = true;
    in_lockout = a->status().state == StateId::ErrorLockout ? in_lockout + 1 : 0;
    if (in_lockout == opt.lockout_reboot_cycles) {
      a.emplace(config);
      b.emplace(config);
      out_a = ScanOutputs{};
      out_b = ScanOutputs{};
      scenario.power_on();
      in_lockout = 0;
      ++power_cycles;
    }
  }
  if (!describe) {
    std::string missed;  // BOOT lasts no full cycle
    for (const StateId st : safestate::kAllStates) {
      if (st != StateId::Boot && !visited[static_cast<std::size_t>(st)]) missed += " " + std::string(to_string(st));
    }
    if (!missed.empty()) {
      std::printf("crosscheck: states never reached (compared nowhere):%s\n", missed.c_str());
      if (opt.require_every_state) return 1;
    }
    std::printf("crosscheck: %" PRIu64 " cycles, %" PRIu64 " steps, %" PRIu64 " power cycles, seed %" PRIu64
                ": no divergence (status record and outputs equal after every step)\n",
                opt.cycles, steps, power_cycles, opt.seed);
  }
  return 0;
}

bool parse_u64(const char* s, std::uint64_t& v) {
  char* end = nullptr;
  v = std::strtoull(s, &end, 10);
  return end != s && *end == '\0';
}

int usage() {
  std::fprintf(stderr,
               "usage: bench_cycle ssm|switch [--cycles N] [--seed S] [--per-cycle] [--quiet]\n"
               "       bench_cycle crosscheck [--cycles N] [--seed S] [--require-every-state]\n"
               "       bench_cycle describe --cycle K [--seed S]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  Options opt;
  opt.impl = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--cycles" && i + 1 < argc) {
      if (!parse_u64(argv[++i], opt.cycles)) return usage();
    } else if (a == "--seed" && i + 1 < argc) {
      if (!parse_u64(argv[++i], opt.seed)) return usage();
    } else if (a == "--cycle" && i + 1 < argc) {
      if (!parse_u64(argv[++i], opt.describe_cycle)) return usage();
    } else if (a == "--per-cycle") {
      opt.per_cycle = true;
    } else if (a == "--quiet") {
      opt.quiet = true;
    } else if (a == "--require-every-state") {
      opt.require_every_state = true;
    } else {
      return usage();
    }
  }
  if (opt.impl == "crosscheck") return crosscheck(opt, false);
  if (opt.impl == "describe") return crosscheck(opt, true);
  if (opt.impl == "ssm") {
    Runner<safestate::SystemStateManager> r(opt);
    r.run();
    if (!opt.quiet) r.print("ssm");
    return 0;
  }
  if (opt.impl == "switch") {
    Runner<safestate_bench::SwitchCaseSsm> r(opt);
    r.run();
    if (!opt.quiet) r.print("switch");
    return 0;
  }
  return usage();
}
