// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 10: the fieldbus / cycle watchdog is computed in the core from the process
// image's cycle counter and working counter (design §2 "Fieldbus watchdog", C24).
#include <gtest/gtest.h>

#include <cstdint>

#include "safestate/fieldbus_watchdog.hpp"

namespace {

using safestate::FieldbusWatchdog;

constexpr std::uint16_t kWkc = 18;

TEST(Issue29_Item10_FieldbusWatchdog, FreshCompleteFramesEveryCycleStayHealthy) {
  FieldbusWatchdog w(kWkc, 0);
  for (std::uint32_t k = 0; k < 70000; ++k) {  // across the 16-bit wrap
    ASSERT_TRUE(w.update(static_cast<std::uint16_t>(k + 65000U), kWkc)) << k;
  }
  EXPECT_EQ(w.missed_cycles(), 0U);
}

TEST(Issue29_Item10_FieldbusWatchdog, AWrongWorkingCounterIsALoss) {
  FieldbusWatchdog w(kWkc, 0);
  ASSERT_TRUE(w.update(1, kWkc));
  EXPECT_FALSE(w.update(2, kWkc - 3));  // one drive did not process the frame
}

TEST(Issue29_Item10_FieldbusWatchdog, AStalledCounterIsALoss) {
  FieldbusWatchdog w(kWkc, 0);
  ASSERT_TRUE(w.update(7, kWkc));
  EXPECT_FALSE(w.update(7, kWkc));  // the same frame again: the bus delivered nothing new
}

TEST(Issue29_Item10_FieldbusWatchdog, ACounterJumpIsAMissedCycleOverrun) {
  FieldbusWatchdog w(kWkc, 0);
  ASSERT_TRUE(w.update(7, kWkc));
  EXPECT_FALSE(w.update(9, kWkc));  // the control cycle missed frame 8
}

TEST(Issue29_Item10_FieldbusWatchdog, TheToleranceCountsMissedCyclesInARow) {
  FieldbusWatchdog w(kWkc, 2);
  ASSERT_TRUE(w.update(1, kWkc));
  EXPECT_TRUE(w.update(1, kWkc));  // 1 missed
  EXPECT_TRUE(w.update(2, 0));     // 2 missed (WKC wrong)
  EXPECT_TRUE(w.update(2, kWkc));  // fresh: the streak ends
  EXPECT_EQ(w.missed_cycles(), 0U);
  EXPECT_TRUE(w.update(4, kWkc));   // one frame skipped: 1 missed
  EXPECT_TRUE(w.update(4, kWkc));   // 2 missed
  EXPECT_FALSE(w.update(4, kWkc));  // 3 > 2: lost
  FieldbusWatchdog jump(kWkc, 2);
  ASSERT_TRUE(jump.update(100, kWkc));
  EXPECT_FALSE(jump.update(104, kWkc));  // three frames skipped at once
}

TEST(Issue29_Item10_FieldbusWatchdog, ALossIsLatched) {
  FieldbusWatchdog w(kWkc, 0);
  ASSERT_TRUE(w.update(1, kWkc));
  ASSERT_FALSE(w.update(1, kWkc));
  for (std::uint16_t k = 2; k < 100; ++k) EXPECT_FALSE(w.update(k, kWkc));
}

TEST(Issue29_Item10_FieldbusWatchdog, AZeroImageIsALossFromTheFirstCycle) {
  FieldbusWatchdog w(kWkc, 0);
  EXPECT_FALSE(w.update(0, 0));
  FieldbusWatchdog no_expectation(0, 0);  // an expected WKC of 0 would accept silence
  EXPECT_FALSE(no_expectation.update(0, 0));
}

TEST(Issue29_Item10_FieldbusWatchdog, TheFirstCompleteFrameSetsTheReference) {
  FieldbusWatchdog w(kWkc, 0);
  EXPECT_FALSE(w.has_reference());
  EXPECT_TRUE(w.update(4242, kWkc));
  EXPECT_TRUE(w.has_reference());
  EXPECT_EQ(w.last_counter(), 4242);
  EXPECT_TRUE(w.update(4243, kWkc));
}

}  // namespace
