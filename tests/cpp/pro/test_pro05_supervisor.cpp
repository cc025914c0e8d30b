// GoogleTest of the runtime supervisor rows X01..S02 (PRO-05, docs/design/protection.md
// §6-§9) and the audit of the C++ table against the page's row ids.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <sstream>
#include <string>

#include "safestate/pro/runtime_supervisor.hpp"

namespace {

using namespace safestate::pro;  // NOLINT

SupervisorInputs all(UnitStatus s) {
  SupervisorInputs in;
  in.status.fill(s);
  return in;
}

std::string row(const SupervisorStep& s) { return std::string(s.row->id); }

TEST(PRO05_Supervisor, RunOnlyWhenEveryReadinessGatePassed) {
  RuntimeSupervisor sup(5);
  SupervisorInputs in = all(UnitStatus::ready);
  in.status[index(UnitId::comms)] = UnitStatus::init;
  EXPECT_EQ(row(sup.tick(in)), "I04");
  EXPECT_EQ(sup.state(), SupervisorState::init);
  EXPECT_EQ(sup.init_ticks(), 1U);
  in.status[index(UnitId::comms)] = UnitStatus::ready;
  const SupervisorStep s = sup.tick(in);
  EXPECT_EQ(row(s), "I01");
  EXPECT_EQ(s.mode, DispatchMode::all);
  EXPECT_EQ(sup.init_ticks(), 0U);
}

TEST(PRO05_Supervisor, InitTimeoutDegrades) {
  RuntimeSupervisor sup(3);
  const SupervisorInputs in = all(UnitStatus::init);
  EXPECT_EQ(row(sup.tick(in)), "I04");
  EXPECT_EQ(row(sup.tick(in)), "I04");
  const SupervisorStep s = sup.tick(in);
  EXPECT_EQ(row(s), "I03");
  EXPECT_TRUE(s.entered_degraded);
  EXPECT_EQ(s.mode, DispatchMode::critical_only);
}

TEST(PRO05_Supervisor, AFailedUnitOrFatalFaultOrBadWatchdogDegradesAndRecoveryNeedsAllThree) {
  RuntimeSupervisor sup(5);
  SupervisorInputs in = all(UnitStatus::ready);
  ASSERT_EQ(row(sup.tick(in)), "I01");
  in.fatal_fault = true;
  EXPECT_EQ(row(sup.tick(in)), "R01");
  in.fatal_fault = false;
  in.watchdog_ok = false;
  EXPECT_EQ(row(sup.tick(in)), "D02");  // the watchdog is not fine yet
  in.watchdog_ok = true;
  in.status[index(UnitId::control)] = UnitStatus::failed;
  EXPECT_EQ(row(sup.tick(in)), "D02");  // a required service not ready
  in.status[index(UnitId::control)] = UnitStatus::ready;
  const SupervisorStep s = sup.tick(in);
  EXPECT_EQ(row(s), "D01");
  EXPECT_TRUE(s.recovered);
  in.status[index(UnitId::comms)] = UnitStatus::failed;  // comms is a required service too
  EXPECT_EQ(row(sup.tick(in)), "R01");
}

TEST(PRO05_Supervisor, ShutdownGoesThroughTheStopOrderOutputsFirstAndCompletesWhenAllStopped) {
  RuntimeSupervisor sup(5);
  SupervisorInputs in = all(UnitStatus::ready);
  ASSERT_EQ(row(sup.tick(in)), "I01");
  in.shutdown_requested = true;
  SupervisorStep s = sup.tick(in);
  EXPECT_EQ(row(s), "X01");
  EXPECT_TRUE(s.stop_requested);
  EXPECT_TRUE(sup.stop_target().outputs);
  in.shutdown_requested = false;
  // Nobody reports: the supervisor waits.
  EXPECT_EQ(row(sup.tick(in)), "S02");
  EXPECT_EQ(sup.stop_step(), 1U);
  // A unit stopping out of turn does not advance the order; safety is never stopped first.
  in.outputs_safe_reported = true;
  s = sup.tick(in);
  EXPECT_TRUE(sup.outputs_safe());
  EXPECT_EQ(sup.stop_step(), 2U);
  const UnitId expected[] = {UnitId::comms,      UnitId::diagnostics, UnitId::safety, UnitId::control,
                             UnitId::monitoring, UnitId::dispatcher,  UnitId::timer};
  for (const UnitId u : expected) {
    EXPECT_EQ(sup.stop_target().unit, u);
    in.status[index(u)] = UnitStatus::stopped;
    s = sup.tick(in);
  }
  EXPECT_EQ(row(s), "S01");
  EXPECT_EQ(sup.state(), SupervisorState::stopped);
  EXPECT_EQ(s.mode, DispatchMode::none);
  EXPECT_EQ(row(sup.tick(in)), "T01");
}

TEST(PRO05_Supervisor, ShutdownIsAcceptedFromInitAndFromDegraded) {
  for (const bool degrade_first : {false, true}) {
    RuntimeSupervisor sup(5);
    SupervisorInputs in = all(UnitStatus::init);
    if (degrade_first) {
      in.fatal_fault = true;
      ASSERT_EQ(row(sup.tick(in)), "I02");
    }
    in.shutdown_requested = true;
    EXPECT_EQ(row(sup.tick(in)), "X01");
    EXPECT_EQ(sup.state(), SupervisorState::shutting_down);
  }
}

TEST(PRO05_Supervisor, EveryRowOfThePageIsInTheTableInThePagesOrder) {
  std::ifstream page(std::string(SAFESTATE_SOURCE_DIR) + "/docs/design/protection.md");
  ASSERT_TRUE(page.good());
  std::stringstream text;
  text << page.rdbuf();
  std::string ids;
  std::string line;
  while (std::getline(text, line)) {
    if (line.size() > 6 && line.rfind("| ", 0) == 0 &&
        (line[2] == 'X' || line[2] == 'I' || line[2] == 'R' || line[2] == 'D' || line[2] == 'S' || line[2] == 'T') &&
        std::isdigit(static_cast<unsigned char>(line[3])) != 0 && line[5] == ' ') {
      ids += line.substr(2, 3) + " ";
    }
  }
  std::string table;
  for (const SupervisorRow& r : kSupervisorRows) table += std::string(r.id) + " ";
  EXPECT_EQ(ids, table);
}

}  // namespace
