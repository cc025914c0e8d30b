// SPDX-License-Identifier: Apache-2.0
// Cycle time of the control thread with the operator link attached (issue 16):
//
//   bench_link [--seconds S] [--clients N] [--flood R] [--rounds K] [--control-cpu C] [--bridge-cpu B]
//
// Runs the ControlLoop at 1 ms and the bridge in-process. The control thread runs at
// SCHED_FIFO pinned to CPU C (default 0); the bridge thread and the clients (this thread)
// are pinned to CPU B (default 1), so the bridge's work never runs on the control core.
// K rounds (default 5) alternate S/K seconds with no client and S/K seconds with N observers
// (default 100) each reading the 20 Hz status broadcast plus one controlling client sending
// heartbeats (and, with --flood R, R requests per second): the machine's load drifts over
// both configurations alike. Prints the load average at start, the placement obtained, the
// cycle's execution time p50 / p99 / max for both and the ratio of the p99s (target <= 1.1).
// A measurement, never a pass/fail test: the figures depend on the machine and its load.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "link_ws_client.hpp"
#include "safestate/link/bridge.hpp"
#include "safestate/link/control_loop.hpp"
#include "safestate/link/thread_placement.hpp"

namespace {

using namespace safestate::link;  // NOLINT
using Clock = std::chrono::steady_clock;

struct Placement {
  int control_cpu{0};
  int bridge_cpu{1};
  std::atomic<bool> control_pinned{true};
  std::atomic<bool> control_realtime{true};
};

// One round of `seconds` with `clients` observers (+ 1 controller when clients > 0); the
// cycle times are added to `into`.
void measure(ControlLoop& loop, Bridge& bridge, Placement& where, int seconds, int clients, int flood,
             CycleTimeHistogram& into) {
  std::vector<std::unique_ptr<link_test::WsClient>> cs;
  for (int i = 0; i < clients; ++i) {
    cs.push_back(std::make_unique<link_test::WsClient>());
    if (!cs.back()->connect(bridge.port())) {
      std::fprintf(stderr, "bench_link: client %d could not connect\n", i);
      std::exit(1);
    }
  }
  link_test::WsClient op;
  if (clients > 0) {
    (void)op.connect(bridge.port());
    (void)op.send_text(R"({"v":1,"type":"request_control","id":1,"token":"bench"})");
    (void)op.wait_for("confirm_control", 5000);
  }
  std::atomic<bool> stop{false};
  std::thread control([&] {
    // As safestate_link does: a real-time priority when permitted (root / CAP_SYS_NICE), so
    // the figures measure the cycle, not the scheduler's choice among the machine's jobs.
    if (!pin_current_thread(where.control_cpu)) where.control_pinned.store(false);
    if (!make_current_thread_realtime()) where.control_realtime.store(false);
    loop.run(stop, std::chrono::microseconds(1000));
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // warm-up
  loop.clear_cycle_times();
  const auto end = Clock::now() + std::chrono::seconds(seconds);
  auto next_beat = Clock::now();
  long sent = 0;
  const auto start = Clock::now();
  while (Clock::now() < end) {
    if (clients > 0) {
      if (Clock::now() >= next_beat) {
        (void)op.send_text(R"({"v":1,"type":"heartbeat"})");
        next_beat += std::chrono::milliseconds(50);
      }
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      while (flood > 0 && sent < static_cast<long>(elapsed * flood)) {
        (void)op.send_text(R"({"v":1,"type":"command","id":7,"command":"PAUSE"})");
        ++sent;
      }
      (void)op.pump(0);
      for (auto& c : cs) (void)c->pump(0);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  stop.store(true);
  control.join();
  into.merge(loop.cycle_times());
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return in ? one + " " + five + " " + fifteen : std::string("unknown");
}

void print_row(const std::string& label, const CycleTimeHistogram& h) {
  std::printf("%-34s %8.1f %8.1f %8.1f %8llu\n", label.c_str(), h.percentile_us(0.50), h.percentile_us(0.99),
              h.max_us(), static_cast<unsigned long long>(h.count()));
}

}  // namespace

int main(int argc, char** argv) {
  int seconds = 10;
  int clients = 100;
  int flood = 0;
  int rounds = 5;
  Placement where;
  for (int i = 1; i < argc; i += 2) {
    const std::string_view a = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_link: %s expects a number\n", argv[i]);
      return 2;
    }
    const int v = std::atoi(argv[i + 1]);
    if (a == "--seconds") seconds = v;
    else if (a == "--clients") clients = v;
    else if (a == "--flood") flood = v;
    else if (a == "--rounds") rounds = v;
    else if (a == "--control-cpu") where.control_cpu = v;
    else if (a == "--bridge-cpu") where.bridge_cpu = v;
    else {
      std::fprintf(
          stderr,
          "bench_link: unknown argument '%s' (expected --seconds, --clients, --flood, --rounds, --control-cpu, "
          "--bridge-cpu)\n",
          argv[i]);
      return 2;
    }
  }
  if (rounds < 1 || seconds < rounds) {
    std::fprintf(stderr, "bench_link: expected --rounds >= 1 and --seconds >= --rounds (whole seconds per round)\n");
    return 2;
  }
  std::printf("load average at start: %s (%u CPUs online)\n", load_average().c_str(),
              std::thread::hardware_concurrency());
  const bool main_pinned = pin_current_thread(where.bridge_cpu);  // the clients
  static ControlLoop loop;
  BridgeOptions options;
  options.token = "bench";
  Bridge bridge(loop, options);
  std::atomic<bool> bridge_pinned{true};
  std::thread bridge_thread([&] {
    if (!pin_current_thread(where.bridge_cpu)) bridge_pinned.store(false);
    bridge.run();
  });
  static CycleTimeHistogram none;
  static CycleTimeHistogram many;
  for (int r = 0; r < rounds; ++r) {
    measure(loop, bridge, where, seconds / rounds, 0, 0, none);
    measure(loop, bridge, where, seconds / rounds, clients, flood, many);
  }
  bridge.stop();
  bridge_thread.join();
  std::printf("placement: control thread on CPU %d (%s, %s); bridge thread and clients on CPU %d (%s)\n",
              where.control_cpu, where.control_pinned ? "pinned" : "NOT pinned",
              where.control_realtime ? "SCHED_FIFO" : "NOT real-time: needs root or CAP_SYS_NICE", where.bridge_cpu,
              bridge_pinned && main_pinned ? "pinned" : "NOT pinned");
  std::printf("control cycle execution time (us; 0.1 us buckets), 1 ms period, %d rounds of %d s + %d s\n", rounds,
              seconds / rounds, seconds / rounds);
  std::printf("%-34s %8s %8s %8s %8s\n", "clients", "p50", "p99", "max", "cycles");
  print_row("0", none);
  std::string label = std::to_string(clients) + " observers + 1 controller";
  if (flood > 0) label += " (" + std::to_string(flood) + " req/s)";
  print_row(label, many);
  const double p99_none = none.percentile_us(0.99);
  std::printf("p99 ratio (with / without clients): %.2f (target <= 1.10)\n",
              p99_none > 0 ? many.percentile_us(0.99) / p99_none : 0.0);
  std::printf("load average at end: %s\n", load_average().c_str());
  std::printf("bridge: status frames dropped %llu, queue full %llu, busy %llu, requests %llu\n",
              static_cast<unsigned long long>(bridge.counters().status_frames_dropped.load()),
              static_cast<unsigned long long>(bridge.counters().queue_full.load()),
              static_cast<unsigned long long>(bridge.counters().busy.load()),
              static_cast<unsigned long long>(bridge.counters().requests.load()));
  return 0;
}
