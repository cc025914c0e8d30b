// SPDX-License-Identifier: Apache-2.0
// Cycle time of the control thread with the operator link attached (issue 16):
//
//   bench_link [--seconds S] [--clients N] [--flood R]
//
// Runs the ControlLoop at 1 ms and the bridge in-process, first with no client, then with
// N observers (default 100) each reading the 20 Hz status broadcast, plus one controlling
// client sending heartbeats and, with --flood R, R requests per second. Prints the cycle's
// execution time p50 / p99 / max for both runs and the ratio of the p99s (target <= 1.1).
// A measurement, never a pass/fail test: the figures depend on the machine and its load.
#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "link_ws_client.hpp"
#include "safestate/link/bridge.hpp"
#include "safestate/link/control_loop.hpp"

namespace {

using namespace safestate::link;  // NOLINT
using Clock = std::chrono::steady_clock;

struct Figures {
  double p50, p99, max;
  unsigned long long cycles;
};

Figures measure(ControlLoop& loop, Bridge& bridge, int seconds, int clients, int flood) {
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
    sched_param p{};
    p.sched_priority = sched_get_priority_max(SCHED_FIFO) / 2;
    (void)pthread_setschedparam(pthread_self(), SCHED_FIFO, &p);
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
  const CycleTimeHistogram& h = loop.cycle_times();
  return Figures{h.percentile_us(0.50), h.percentile_us(0.99), h.max_us(),
                 static_cast<unsigned long long>(h.count())};
}

}  // namespace

int main(int argc, char** argv) {
  int seconds = 5;
  int clients = 100;
  int flood = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string_view a = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if (a == "--seconds") seconds = v;
    else if (a == "--clients") clients = v;
    else if (a == "--flood") flood = v;
    else {
      std::fprintf(stderr, "bench_link: unknown argument '%s' (expected --seconds, --clients, --flood)\n", argv[i]);
      return 2;
    }
  }
  static ControlLoop loop;
  BridgeOptions options;
  options.token = "bench";
  Bridge bridge(loop, options);
  std::thread bridge_thread([&] { bridge.run(); });
  const Figures none = measure(loop, bridge, seconds, 0, 0);
  const Figures many = measure(loop, bridge, seconds, clients, flood);
  bridge.stop();
  bridge_thread.join();
  std::printf("control cycle execution time (us; 0.1 us buckets), %d s each, 1 ms period\n", seconds);
  std::printf("%-34s %8s %8s %8s %8s\n", "clients", "p50", "p99", "max", "cycles");
  std::printf("%-34s %8.1f %8.1f %8.1f %8llu\n", "0", none.p50, none.p99, none.max, none.cycles);
  std::string label = std::to_string(clients) + " observers + 1 controller";
  if (flood > 0) label += " (" + std::to_string(flood) + " req/s)";
  std::printf("%-34s %8.1f %8.1f %8.1f %8llu\n", label.c_str(), many.p50, many.p99, many.max, many.cycles);
  std::printf("p99 ratio (with / without clients): %.2f (target <= 1.10)\n", none.p99 > 0 ? many.p99 / none.p99 : 0.0);
  std::printf("bridge: status frames dropped %llu, queue full %llu, requests %llu\n",
              static_cast<unsigned long long>(bridge.counters().status_frames_dropped.load()),
              static_cast<unsigned long long>(bridge.counters().queue_full.load()),
              static_cast<unsigned long long>(bridge.counters().requests.load()));
  return 0;
}
