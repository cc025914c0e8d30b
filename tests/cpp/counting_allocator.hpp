// SPDX-License-Identifier: Apache-2.0
// The no-heap tests' counting allocator: replaces the global operator new/delete of the test
// executable that includes this header (include it from exactly one file per executable).
// While g_counting is set, every operator new is counted in g_allocations.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

inline std::atomic<std::uint64_t> g_allocations{0};
inline std::atomic<bool> g_counting{false};
// A test whose other threads allocate by design (the operator link's bridge and clients)
// sets g_count_marked_threads_only and marks the thread it measures (the control thread).
inline std::atomic<bool> g_count_marked_threads_only{false};
inline thread_local bool t_marked_thread = false;

inline bool counting_now() {
  return g_counting.load(std::memory_order_relaxed) &&
         (!g_count_marked_threads_only.load(std::memory_order_relaxed) || t_marked_thread);
}

inline void* counted_alloc(std::size_t size) {
  if (counting_now()) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* operator new(std::size_t size) { return counted_alloc(size); }
void* operator new[](std::size_t size) { return counted_alloc(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (counting_now()) g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& t) noexcept { return operator new(size, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
