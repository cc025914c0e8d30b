// SPDX-License-Identifier: Apache-2.0
// Issue 16 / RSM-15 with the operator link attached: while 50 WebSocket clients are
// connected (one controlling client jogging with heartbeats, observers reading, one sending
// malformed frames, one never reading), the control thread runs its cycles and makes no
// heap allocation. Global operator new is replaced by the counting allocator of the no-heap
// tests (counting_allocator.hpp), restricted to the control thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "counting_allocator.hpp"
#include "link_ws_client.hpp"
#include "safestate/link/bridge.hpp"
#include "safestate/link/control_loop.hpp"

namespace {

using namespace safestate;        // NOLINT: test code
using namespace safestate::link;  // NOLINT: test code
using link_test::WsClient;

TEST(RSM15_OperatorLinkNoHeap, TheControlCycleAllocatesNothingWith50ClientsConnected) {
  static ControlLoop loop;
  BridgeOptions options;
  options.token = "secret";
  Bridge bridge(loop, options);
  std::thread bridge_thread([&] { bridge.run(); });

  std::atomic<bool> stop{false};
  g_count_marked_threads_only.store(true);
  std::thread control([&] {
    t_marked_thread = true;
    while (!stop.load()) {
      loop.run_one_cycle();
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  });

  std::vector<std::unique_ptr<WsClient>> clients;
  for (int i = 0; i < 50; ++i) {
    clients.push_back(std::make_unique<WsClient>());
    ASSERT_TRUE(clients.back()->connect(bridge.port())) << "client " << i;
  }
  WsClient& op = *clients[0];
  ASSERT_TRUE(op.send_text(R"({"v":1,"type":"request_control","id":1,"token":"secret"})"));
  ASSERT_TRUE(op.wait_for("confirm_control", 5000));
  ASSERT_TRUE(op.send_text(R"({"v":1,"type":"plant","id":2,"set":{"selector":"T1","enabling":"MIDDLE"}})"));
  ASSERT_TRUE(op.wait_for("plant_set", 5000));
  const std::uint64_t cycles_before = loop.cycles();
  g_counting.store(true);

  ASSERT_TRUE(op.send_text(R"({"v":1,"type":"command","id":3,"command":"SERVO_ON"})"));
  std::string result;
  ASSERT_TRUE(op.wait_for("\"id\":3", 5000, &result));
  EXPECT_NE(result.find("ACCEPTED"), std::string::npos) << result;
  for (int k = 0; k < 40; ++k) {  // two seconds of traffic
    ASSERT_TRUE(op.send_text(R"({"v":1,"type":"heartbeat"})"));
    if (k == 10) {
      ASSERT_TRUE(op.send_text(
          R"({"v":1,"type":"command","id":4,"command":"JOG_START","axis":2,"direction":1,"speed_mm_s":400})"));
    }
    ASSERT_TRUE(clients[1]->send_text("{not json"));
    ASSERT_TRUE(clients[2]->send_text(R"({"v":1,"type":"command","id":9,"command":"RESET"})"));
    for (std::size_t i = 0; i + 1 < clients.size(); ++i) (void)clients[i]->pump(1);  // the last never reads
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::uint64_t cycles_after = loop.cycles();
  g_counting.store(false);
  const std::uint64_t allocations = g_allocations.load();
  stop.store(true);
  control.join();
  bridge.stop();
  bridge_thread.join();

  EXPECT_EQ(allocations, 0U) << "heap allocations on the control thread with 50 clients connected";
  EXPECT_GT(cycles_after, cycles_before) << "the control thread made no progress";
  EXPECT_GT(bridge.counters().malformed_json.load(), 0U);
  EXPECT_GT(bridge.counters().observer_commands_refused.load(), 0U);
  CellStatus st;
  ASSERT_TRUE(loop.read_status(st));
  EXPECT_EQ(st.status.state, StateId::ManualJogging);
  EXPECT_EQ(st.outputs.commanded_speed_mm_s, 250);  // T1: clamped (K29)
}

}  // namespace
