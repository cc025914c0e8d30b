// GoogleTest of the active-object runtime (PRO-05, docs/design/protection.md §1): bounded
// queues that reject and count an overflow, run-to-completion in FIFO order, the tick source.
#include <gtest/gtest.h>

#include <vector>

#include "safestate/pro/active_object.hpp"
#include "safestate/pro/event_queue.hpp"
#include "safestate/pro/tick_source.hpp"

namespace {

using namespace safestate::pro;  // NOLINT

class Recorder final : public ActiveObject {
 public:
  Recorder() : ActiveObject(AoId::diagnostics) {}
  std::vector<std::uint32_t> seen;
  int depth = 0;
  int max_depth = 0;
  void stop_now() { set_status(UnitStatus::stopped); }

 protected:
  void on_event(const AoEvent& e) noexcept override {
    ++depth;
    max_depth = depth > max_depth ? depth : max_depth;
    seen.push_back(e.tick);
    // Posting to itself during a dispatch queues the event; it runs after this one ends.
    if (e.tick == 1) (void)post(AoEvent{AoSignal::tick, 99, 0, 0});
    --depth;
  }
};

TEST(PRO05_ActiveObject, AFullQueueRejectsThePostWithAReasonAndCountsIt) {
  EventQueue<AoEvent, 4> q;
  for (std::uint32_t i = 0; i < 4; ++i) EXPECT_EQ(q.post(AoEvent{AoSignal::tick, i, 0, 0}), PostResult::ok);
  EXPECT_EQ(q.post(AoEvent{AoSignal::tick, 4, 0, 0}), PostResult::queue_full);
  EXPECT_EQ(q.post(AoEvent{AoSignal::tick, 5, 0, 0}), PostResult::queue_full);
  EXPECT_EQ(q.overflow_count(), 2U);
  AoEvent e;
  ASSERT_TRUE(q.take(e));
  EXPECT_EQ(e.tick, 0U);  // the queued events are intact, oldest first
  EXPECT_EQ(q.post(AoEvent{AoSignal::tick, 6, 0, 0}), PostResult::ok);
}

TEST(PRO05_ActiveObject, RunToCompletionHandlesEveryEventOneAtATimeInFifoOrder) {
  Recorder ao;
  for (std::uint32_t i = 1; i <= 3; ++i) ASSERT_EQ(ao.post(AoEvent{AoSignal::tick, i, 0, 0}), PostResult::ok);
  EXPECT_EQ(ao.run_to_completion(), 4U);
  EXPECT_EQ(ao.seen, (std::vector<std::uint32_t>{1, 2, 3, 99}));
  EXPECT_EQ(ao.max_depth, 1);  // never re-entered
  EXPECT_EQ(ao.queued(), 0U);
}

TEST(PRO05_ActiveObject, QueueOverflowIsReportedByTheAo) {
  Recorder ao;
  for (std::size_t i = 0; i < ActiveObject::kQueueCapacity; ++i) {
    ASSERT_EQ(ao.post(AoEvent{}), PostResult::ok);
  }
  EXPECT_EQ(ao.post(AoEvent{}), PostResult::queue_full);
  EXPECT_EQ(ao.overflow_count(), 1U);
}

TEST(PRO05_ActiveObject, AStoppedAoTakesNoMoreEvents) {
  Recorder ao;
  ao.stop_now();
  EXPECT_EQ(ao.post(AoEvent{}), PostResult::stopped);
  EXPECT_EQ(ao.run_to_completion(), 0U);
}

TEST(PRO05_TickSource, TicksCountFromOneAndTheSourceReportsItsStatus) {
  TickSource t;
  EXPECT_EQ(t.status(), UnitStatus::init);
  t.start();
  EXPECT_EQ(t.status(), UnitStatus::ready);
  EXPECT_EQ(t.advance(), 1U);
  EXPECT_EQ(t.advance(), 2U);
  t.stop();
  EXPECT_EQ(t.status(), UnitStatus::stopped);
  EXPECT_EQ(kTickPeriodMs * 10, 1000U);  // the 1 s budget is ten ticks
}

}  // namespace
