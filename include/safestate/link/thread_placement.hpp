// SPDX-License-Identifier: Apache-2.0
// Where the operator link's threads run (design §11): the control thread gets a real-time
// priority and a core of its own; the bridge (and, in the bench, the clients) another core.
// On a shared machine this keeps the bridge's work out of the control thread's core and its
// caches, so the cycle time does not grow with the number of connected clients.
// Both are best effort: they need root or CAP_SYS_NICE (priority) and the CPU to exist.
#pragma once

#include <pthread.h>
#include <sched.h>

namespace safestate::link {

/// Pins the calling thread to `cpu`; FALSE when that is not possible (no such CPU, cpuset).
[[nodiscard]] inline bool pin_current_thread(int cpu) noexcept {
  if (cpu < 0 || cpu >= CPU_SETSIZE) return false;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

/// SCHED_FIFO at half the maximum priority for the calling thread; FALSE without privileges.
[[nodiscard]] inline bool make_current_thread_realtime() noexcept {
  sched_param p{};
  p.sched_priority = sched_get_priority_max(SCHED_FIFO) / 2;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
}

}  // namespace safestate::link
