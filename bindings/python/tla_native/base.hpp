// SPDX-License-Identifier: Apache-2.0
// What every part of the native core uses: value kinds and the reserved ids, the
// evaluation error, hashing, thread CPU time.
#pragma once

#include <time.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace safestate::tla_native {

enum Kind : uint8_t { K_BOOL, K_INT, K_STR, K_MV, K_SEQ, K_FUN, K_SET };

constexpr uint32_t kIntTag = 0x80000000u;
constexpr int64_t kIntBias = int64_t(1) << 30;
constexpr uint32_t kFalse = 0, kTrue = 1;
constexpr uint32_t kUnset = 0xFFFFFFFFu;

// An evaluation error: it ends the search with its text and location (the Python
// engine then re-checks the model for TLC's exact report).
struct EvalFailure {
  std::string message;
  int loc;
};

[[noreturn]] inline void fail(const std::string& msg, int loc) { throw EvalFailure{msg, loc}; }

inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

inline uint64_t mix(uint64_t h, uint64_t x) {
  h ^= x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 32);
}

// The hash of an id array: one xor and one multiply per id (a bijection of the running
// hash for each id), the high bits folded into the low ones at the end (tables index by
// the low bits).  Only a table's probe order depends on it, never a result.
inline uint64_t hash_ids(uint64_t seed, const uint32_t* x, size_t n) {
  constexpr uint64_t kMul = 0x9e3779b97f4a7c15ULL;
  uint64_t h = (seed + n) * kMul;
  for (size_t i = 0; i < n; ++i) h = (h ^ x[i]) * kMul;
  h ^= h >> 32;
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 29);
}

}  // namespace safestate::tla_native
