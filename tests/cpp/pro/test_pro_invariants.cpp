// The invariants of models/Protection.tla (INV_PRO_*) asserted on the C++ ao_safety for
// every pre-state and every snapshot of the model's CI alphabet (limits 2 / 1 / 3,
// temperatures 0..3, voltages 0..4, valid or not, clear or not) -- the C++ side of the
// model's statements until the conformance adapter exists (docs/design/protection.md §11).
#include <gtest/gtest.h>

#include <cstdint>

#include "safestate/pro/ao_safety.hpp"

namespace {

using safestate::pro::AoSafety;
using safestate::pro::FaultCause;
using safestate::pro::ProtectionLimits;
using safestate::pro::ProtectionState;
using safestate::pro::SafetyResult;
using safestate::pro::SensorSnapshot;

constexpr ProtectionLimits kModelLimits{2, 1, 3};

// ao_safety brought to NORMAL or PROTECTION (a hazardous snapshot enters it).
AoSafety in_state(ProtectionState state) {
  AoSafety safety(kModelLimits);
  if (state == ProtectionState::protection) {
    (void)safety.dispatch(SensorSnapshot{3, 2, true, false}, 1);
  }
  return safety;
}

TEST(PRO_Invariants, EveryPreStateAndSnapshotOfTheModelAlphabet) {
  int checked = 0;
  for (const ProtectionState before : {ProtectionState::normal, ProtectionState::protection}) {
    for (std::int16_t temp = 0; temp <= 3; ++temp) {
      for (std::uint16_t volt = 0; volt <= 4; ++volt) {
        for (const bool valid : {false, true}) {
          for (const bool clear : {false, true}) {
            AoSafety safety = in_state(before);
            const SensorSnapshot s{temp, volt, valid, clear};
            const bool hazard = temp > 2 || volt < 1 || volt > 3 || !valid;
            const SafetyResult result = safety.dispatch(s, 2);
            const auto& ctx = safety.context();
            const bool after = ctx.protection_state == ProtectionState::protection;
            const bool was = before == ProtectionState::protection;
            // INV_PRO_HAZARD_PROTECTS (PRO-01)
            EXPECT_TRUE(!hazard || after);
            // INV_PRO_LATCH (PRO-02)
            EXPECT_TRUE(!(was && !after) || (clear && !hazard));
            EXPECT_TRUE(!(was && clear && hazard) || result == SafetyResult::latch_blocked);
            // INV_PRO_RESULT (PRO-02)
            EXPECT_EQ(result == SafetyResult::protection_entered, !was && after);
            EXPECT_TRUE(result != SafetyResult::latch_blocked || (was && clear));
            // INV_PRO_OVERRIDE (PRO-03)
            EXPECT_EQ(ctx.latch_active, after);
            EXPECT_EQ(ctx.override_active, after);
            EXPECT_EQ(safety.fan_output(0) == safestate::pro::kSafeFanCommandPercent, after);
            EXPECT_TRUE(result != SafetyResult::protection_entered || safety.last_fault_event() != FaultCause::none);
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, 160);
}

}  // namespace
