// SPDX-License-Identifier: Apache-2.0
// Issue 16, design §11 and row C26: losing the operator link (heartbeat expired: client
// lost, hung or closed) stops a jog with a Cat 2 stop within the period + one cycle, and
// changes nothing else. Also the two wait-free primitives the link shares with the cycle.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>

#include "safestate/link/heartbeat_monitor.hpp"
#include "safestate/link/seqlock.hpp"
#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code
using safestate::link::HeartbeatMonitor;
using safestate::link::Seqlock;

TEST(RSM13_OperatorLinkLoss, ZeroInitialisedInputsReadTheLinkAsLost) { EXPECT_FALSE(ScanInputs{}.operator_link_ok); }

TEST(RSM13_OperatorLinkLoss, LinkLostWhileJoggingIsACat2StopToHoldWithTheJogKept) {
  Rig r;
  r.to_jogging(SelectorReading::T1, 100);
  ASSERT_GT(r.out.commanded_speed_mm_s, 0);
  r.in.operator_link_ok = false;
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C26");
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat2);
  EXPECT_EQ(r.st().resume_to, ResumeTarget::ManualJogging);
  EXPECT_EQ(r.out.commanded_speed_mm_s, 0);
  EXPECT_TRUE(r.out.contactor_closed && r.out.drive_enable && r.out.ramp_down_request);
  EXPECT_EQ(r.out.axes[1], AxisState::Stopping);
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Hold);
  // A new controlling client may resume the kept jog (K24) once the link is back.
  r.in.operator_link_ok = true;
  EXPECT_EQ(r.command(Command::resume()), CommandResult::accepted());
  EXPECT_EQ(r.state(), StateId::ManualJogging);
  EXPECT_EQ(r.st().jog_speed_mm_s, 100);
}

TEST(RSM13_OperatorLinkLoss, NothingButAJogReadsTheLink) {
  // AUTO_RUNNING, MANUAL_IDLE and HOLD keep their state with the link lost.
  Rig a;
  a.to_auto_running();
  a.in.operator_link_ok = false;
  a.cycles(5);
  EXPECT_EQ(a.state(), StateId::AutoRunning);
  Rig m;
  m.to_operational(SelectorReading::T1);
  m.in.operator_link_ok = false;
  m.cycles(5);
  EXPECT_EQ(m.state(), StateId::ManualIdle);
  Rig h;
  h.to_hold();
  h.in.operator_link_ok = false;
  h.cycles(5);
  EXPECT_EQ(h.state(), StateId::Hold);
}

TEST(RSM13_OperatorLinkLoss, EnablingReleaseInTheSameCycleIsStillTheCat1OfC14) {
  Rig r;
  r.to_jogging(SelectorReading::T1, 100);
  r.in.operator_link_ok = false;
  r.in.enabling = {EnablePosition::Released, EnablePosition::Released};
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C14");
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
}

TEST(RSM13_HeartbeatMonitor, LostBeforeTheFirstHeartbeat) {
  HeartbeatMonitor hb(10);
  EXPECT_FALSE(hb.sample());
}

TEST(RSM13_HeartbeatMonitor, ExpiresInThePeriodPlusOneCycleAfterTheLastHeartbeat) {
  HeartbeatMonitor hb(10);
  hb.beat();
  EXPECT_TRUE(hb.sample());  // the cycle that sees the heartbeat: age 0
  for (int k = 1; k <= 10; ++k) EXPECT_TRUE(hb.sample()) << "cycle " << k;
  EXPECT_FALSE(hb.sample());  // cycle 11 = period + 1: lost, C26 fires in this cycle
  EXPECT_FALSE(hb.sample());
  hb.beat();
  EXPECT_TRUE(hb.sample());
}

TEST(RSM13_HeartbeatMonitor, AJogRunsWhileHeartbeatsArriveAndStopsWhenTheyStop) {
  HeartbeatMonitor hb(10);
  Rig r;
  r.to_jogging(SelectorReading::T1, 100);
  for (int k = 0; k < 50; ++k) {
    if (k % 10 == 0) hb.beat();  // one heartbeat per period
    r.in.operator_link_ok = hb.sample();
    r.cycle();
    ASSERT_EQ(r.state(), StateId::ManualJogging) << "cycle " << k;
  }
  // The client hangs after the heartbeat of cycle 40: cycles 41..50 still within the period.
  int stopped_after = 0;
  for (int k = 1; k <= 20 && r.state() == StateId::ManualJogging; ++k) {
    r.in.operator_link_ok = hb.sample();
    r.cycle();
    stopped_after = k;
  }
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.out.commanded_speed_mm_s, 0);
  EXPECT_EQ(stopped_after, 2);  // the period (10) minus the 9 cycles already run since cycle 40, + 1
}

struct Snapshot {
  std::uint64_t a;
  std::uint64_t b;
  std::uint64_t c;
};

TEST(OperatorLinkSeqlock, ReadersSeeOnlyConsistentSnapshots) {
  Seqlock<Snapshot> lock;
  Snapshot s{};
  EXPECT_FALSE(lock.try_read(s));  // nothing published yet
  std::atomic<bool> done{false};
  std::atomic<std::uint64_t> torn{0};
  std::atomic<std::uint64_t> reads{0};
  std::thread reader([&] {
    Snapshot got{};
    while (!done.load()) {
      if (lock.try_read(got)) {
        reads.fetch_add(1);
        if (got.b != got.a * 2 || got.c != got.a * 3) torn.fetch_add(1);
      }
    }
  });
  for (std::uint64_t i = 1; i <= 200000; ++i) lock.write(Snapshot{i, 2 * i, 3 * i});
  done.store(true);
  reader.join();
  EXPECT_EQ(torn.load(), 0U);
  ASSERT_TRUE(lock.read(s));
  EXPECT_EQ(s.a, 200000U);
  EXPECT_EQ(lock.version(), 200000U);
}

}  // namespace
