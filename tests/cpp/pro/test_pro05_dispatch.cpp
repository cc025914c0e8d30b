// GoogleTest of the dispatcher (PRO-05, docs/design/protection.md §8): fixed order,
// only READY AOs, no non-critical AO in Degraded, nothing in INIT/STOPPED.
#include <gtest/gtest.h>

#include <vector>

#include "safestate/pro/dispatcher.hpp"

namespace {

using safestate::pro::AoId;
using safestate::pro::dispatch_cycle;
using safestate::pro::DispatchMode;

std::vector<AoId> run(DispatchMode mode, bool comms_ready = true, bool control_ready = true) {
  std::vector<AoId> ran;
  const auto rec = dispatch_cycle(
      mode, [&](AoId ao) { return (ao != AoId::comms || comms_ready) && (ao != AoId::control || control_ready); },
      [&](AoId ao) { ran.push_back(ao); });
  EXPECT_EQ(rec.count, ran.size());
  for (std::size_t i = 0; i < rec.count; ++i) EXPECT_EQ(rec.order[i], ran[i]);
  return ran;
}

TEST(PRO05_Dispatch, RunDispatchesEveryReadyAoInTheFixedOrder) {
  EXPECT_EQ(run(DispatchMode::all),
            (std::vector<AoId>{AoId::monitoring, AoId::control, AoId::safety, AoId::diagnostics, AoId::comms}));
}

TEST(PRO05_Dispatch, DegradedSkipsCommunicationsEvenWhenReady) {
  EXPECT_EQ(run(DispatchMode::critical_only),
            (std::vector<AoId>{AoId::monitoring, AoId::control, AoId::safety, AoId::diagnostics}));
}

TEST(PRO05_Dispatch, AnAoNotReadyIsSkippedWithoutChangingTheOrder) {
  EXPECT_EQ(run(DispatchMode::all, true, false),
            (std::vector<AoId>{AoId::monitoring, AoId::safety, AoId::diagnostics, AoId::comms}));
}

TEST(PRO05_Dispatch, NothingIsDispatchedBeforeRunOrAfterShutdown) { EXPECT_TRUE(run(DispatchMode::none).empty()); }

// Issue 31 item 4: the dispatcher gate exactly as the runtime applies it, and what
// ao_safety evaluated in a cycle.
TEST(PRO05_Dispatch, NoDispatchCycleWhileTheDispatcherIsNotReady) {
  using safestate::pro::dispatch_gate;
  using safestate::pro::UnitStatus;
  for (const DispatchMode m : {DispatchMode::all, DispatchMode::critical_only, DispatchMode::none}) {
    EXPECT_EQ(dispatch_gate(m, UnitStatus::ready), m);
    EXPECT_EQ(dispatch_gate(m, UnitStatus::init), DispatchMode::none);
    EXPECT_EQ(dispatch_gate(m, UnitStatus::failed), DispatchMode::none);
    EXPECT_EQ(dispatch_gate(m, UnitStatus::stopped), DispatchMode::none);
  }
}

TEST(PRO04_Dispatch, SafetyEvaluatesAFreshSnapshotOnlyWithMonitoringBeforeItInTheCycle) {
  using safestate::pro::DispatchRecord;
  using safestate::pro::safety_input_of;
  using safestate::pro::SafetyInput;
  DispatchRecord r;
  EXPECT_EQ(safety_input_of(r), SafetyInput::none);
  r.order[r.count++] = AoId::monitoring;
  r.order[r.count++] = AoId::control;
  EXPECT_EQ(safety_input_of(r), SafetyInput::none);
  r.order[r.count++] = AoId::safety;
  EXPECT_EQ(safety_input_of(r), SafetyInput::fresh);
  DispatchRecord blind;
  blind.order[blind.count++] = AoId::control;
  blind.order[blind.count++] = AoId::safety;
  EXPECT_EQ(safety_input_of(blind), SafetyInput::empty);
}

}  // namespace
