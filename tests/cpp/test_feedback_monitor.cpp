// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 10: contactor and brake feedback monitoring (the component; the manager does
// not read it yet). A welded contactor or a brake that does not follow its command is found
// after the device's switching time.
#include <gtest/gtest.h>

#include "safestate/feedback_monitor.hpp"

namespace {

using safestate::FeedbackFault;
using safestate::FeedbackMonitor;

TEST(Issue29_Item10_FeedbackMonitor, AFeedbackFollowingWithinItsTimeIsNoFault) {
  FeedbackMonitor m(3);
  EXPECT_EQ(m.update(true, false), FeedbackFault::None);  // contactor pulling in
  EXPECT_EQ(m.update(true, false), FeedbackFault::None);
  EXPECT_EQ(m.update(true, false), FeedbackFault::None);
  EXPECT_EQ(m.update(true, true), FeedbackFault::None);  // closed after 3 cycles
  EXPECT_EQ(m.disagreeing_cycles(), 0U);
  EXPECT_EQ(m.update(false, true), FeedbackFault::None);
  EXPECT_EQ(m.update(false, false), FeedbackFault::None);
}

TEST(Issue29_Item10_FeedbackMonitor, AWeldedContactorIsStuckOnAfterItsTime) {
  FeedbackMonitor m(3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(m.update(false, true), FeedbackFault::None) << i;
  EXPECT_EQ(m.update(false, true), FeedbackFault::StuckOn);
}

TEST(Issue29_Item10_FeedbackMonitor, ABrakeThatDoesNotReleaseIsStuckOff) {
  FeedbackMonitor m(0);
  EXPECT_EQ(m.update(true, false), FeedbackFault::StuckOff);
}

TEST(Issue29_Item10_FeedbackMonitor, TheFaultIsLatched) {
  FeedbackMonitor m(1);
  (void)m.update(false, true);
  ASSERT_EQ(m.update(false, true), FeedbackFault::StuckOn);
  EXPECT_EQ(m.update(false, false), FeedbackFault::StuckOn);
  EXPECT_EQ(m.update(true, true), FeedbackFault::StuckOn);
}

TEST(Issue29_Item10_FeedbackMonitor, AChangeOfCommandGivesTheDeviceItsFullTimeAgain) {
  FeedbackMonitor m(2);
  EXPECT_EQ(m.update(true, false), FeedbackFault::None);
  EXPECT_EQ(m.update(true, false), FeedbackFault::None);
  EXPECT_EQ(m.update(false, true), FeedbackFault::None);  // switched off before it closed
  EXPECT_EQ(m.disagreeing_cycles(), 1U);
  EXPECT_EQ(m.update(false, true), FeedbackFault::None);
  EXPECT_EQ(m.update(false, true), FeedbackFault::StuckOn);
}

}  // namespace
