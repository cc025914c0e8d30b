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

}  // namespace
