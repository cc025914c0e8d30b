// SPDX-License-Identifier: Apache-2.0
// RSM-15: no heap allocation after initialisation. This executable replaces the global
// operator new/delete with counting versions and runs 100,000 cycles of random inputs and
// random commands (seeded) through a constructed manager; not one allocation may happen.
#include <gtest/gtest.h>

#include <cstdint>

#include "counting_allocator.hpp"
#include "ssm_random_plant.hpp"
#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT

TEST(RSM15_NoHeap, TheCountingAllocatorSeesAllocations) {
  g_allocations = 0;
  g_counting = true;
  auto* p = new int(3);
  g_counting = false;
  delete p;
  EXPECT_EQ(g_allocations.load(), 1U);
}

TEST(RSM15_NoHeap, HundredThousandRandomCyclesAndCommandsAllocateNothing) {
  Config c = flange_config();
  c.discrepancy_cycles = 8;
  c.arming_timeout_cycles = 25;
  c.max_stop_cycles = 120;
  SystemStateManager m(c);  // construction may allocate (it does not, but it is allowed)
  RandomPlant plant(20240601U);
  std::uint64_t commands = 0;
  std::uint64_t motion_cycles = 0;
  std::uint64_t full = 0;
  std::uint32_t locked = 0;
  std::uint32_t lockouts = 0;
  alignas(SystemStateManager) unsigned char spare[sizeof(SystemStateManager)];
  SystemStateManager* mgr = &m;

  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < 100000; ++i) {
    Command cmd;
    if (plant.next_command(cmd)) {
      ++commands;
      if (mgr->submit(cmd) == SubmitResult::queue_full) ++full;
    }
    const ScanOutputs out =
        mgr->cycle(plant.next(mgr->fieldbus_watchdog(), RandomPlant::at_rest(mgr->outputs()), mgr->outputs()));
    const StatusRecord st = mgr->status();
    (void)mgr->last_rows();
    if (is_motion(st.state)) ++motion_cycles;
    (void)out;
    locked = st.state == StateId::ErrorLockout ? locked + 1 : 0;
    if (locked == 50) {
      // Power cycle in place (placement new: no heap), to keep exploring after a lockout.
      if (mgr != &m) mgr->~SystemStateManager();
      mgr = new (spare) SystemStateManager(c);
      locked = 0;
      ++lockouts;
    }
  }
  g_counting = false;
  if (mgr != &m) mgr->~SystemStateManager();

  EXPECT_EQ(g_allocations.load(), 0U);
  EXPECT_GT(commands, 20000U);
  EXPECT_GT(motion_cycles, 1000U);
  EXPECT_GT(lockouts, 0U);
  EXPECT_GE(full, 0U);
}

}  // namespace
