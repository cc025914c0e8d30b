// SPDX-License-Identifier: Apache-2.0
// SAF-04: the six parameters, their defaults and their conversion into cycles; the
// authority code in Request Control; the periodic queries (design §3, §8).
#include <cmath>
#include <limits>

#include "saf_test_support.hpp"

namespace safestate::saf::test {
namespace {

TEST(SAF04_Parameters, DefaultsInCycles) {
  const Config c{};
  EXPECT_EQ(c.validate(), ConfigError::None);
  const Timing t = c.timing();
  EXPECT_EQ(t.estop_timeout, 2U);
  EXPECT_EQ(t.report_data_timeout, 40U);
  EXPECT_EQ(t.message_interval, 10U);
  EXPECT_EQ(t.check_interval, 20U);
  EXPECT_EQ(c.authority_code, 225);
}

TEST(SAF04_Parameters, TimesRoundUpToWholeCyclesAtLeastOne) {
  Config c{};
  c.estop_timeout_s = 0.11;
  c.message_interval_s = 0.001;
  EXPECT_EQ(c.timing().estop_timeout, 3U);
  EXPECT_EQ(c.timing().message_interval, 1U);
}

TEST(SAF04_Parameters, InvalidValuesAreRejectedWithAReason) {
  Config c{};
  c.cycle_interval_s = -1;
  EXPECT_EQ(c.validate(), ConfigError::CycleIntervalInvalid);
  c = Config{};
  c.estop_timeout_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(c.validate(), ConfigError::TimeInvalid);
  c = Config{};
  c.check_interval_s = 1e9;
  EXPECT_EQ(c.validate(), ConfigError::TooManyCycles);
}

TEST(SAF04_Parameters, AuthorityCodeIsSentInRequestControl) {
  Config c{};
  c.authority_code = 200;
  SafetyService s{c};
  const CycleResult r = run(s, {});
  ASSERT_NE(find(r.outbox, MessageId::RequestControl), nullptr);
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl)->authority, 200);
  EXPECT_EQ(find(r.outbox, MessageId::RequestControl)->component_id, kSafetyComponentId);
}

TEST(SAF04_Parameters, DefaultEstopTimeoutIsTwoCyclesOfFiftyMs) {
  SafetyService s{Config{}};
  (void)run(s, {clear(), health(Health::Normal)});
  EXPECT_EQ(s.observe().state, SafState::Operational);
  (void)run(s, {});
  EXPECT_EQ(s.observe().state, SafState::Operational);  // 50 ms without Set Estop
  (void)run(s, {});
  EXPECT_EQ(s.observe().state, SafState::Emergency);  // 100 ms = ESTOPTIMEOUT without Set Estop
}

TEST(SAF04_Parameters, QueryHealthEveryMessageIntervalQueryControlEveryCheckInterval) {
  SafetyService s{Config{}};
  int health_queries = 0;
  int control_queries = 0;
  for (int i = 0; i < 100; ++i) {  // 5 s in PAIRING (control wanted all along)
    const CycleResult r = run(s, {});
    health_queries += find(r.outbox, MessageId::QueryHealthSummary) != nullptr;
    control_queries += find(r.outbox, MessageId::QueryControl) != nullptr;
  }
  EXPECT_EQ(health_queries, 10);  // every 0.5 s
  EXPECT_EQ(control_queries, 5);  // every 1.0 s
}

TEST(SAF04_Parameters, QueryControlAlsoWhileReleasedToFindALostRelease) {
  SafetyService s{Config{}};
  (void)run(s, {clear(), health(Health::Normal)});
  int control_queries = 0;
  for (int i = 0; i < 40; ++i) {
    control_queries += find(run(s, {clear(), health(Health::Normal)}).outbox, MessageId::QueryControl) != nullptr;
  }
  EXPECT_EQ(control_queries, 2);  // every CHECKINTERVAL (20 cycles)
}

}  // namespace
}  // namespace safestate::saf::test
