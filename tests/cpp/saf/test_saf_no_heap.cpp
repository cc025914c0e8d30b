// SPDX-License-Identifier: Apache-2.0
// SAF-02/SAF-03 real-time rule of the project (as RSM-15): SafetyService::cycle() never
// allocates. This executable counts every global operator new while 100,000 cycles of
// random datagrams (valid, garbage, oversized) run through a constructed service, and while
// the deployed host runs its cycles with the link key (sealing, opening, the intake).
#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "saf_host_rig.hpp"
#include "saf_test_support.hpp"

namespace {
std::atomic<long> g_news{0};
std::atomic<bool> g_on{false};
}  // namespace

// The replacement operator new allocates with malloc, so free is its matching release;
// GCC cannot see that once it inlines the pair.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  if (g_on.load()) ++g_news;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace safestate::saf::test {
namespace {

TEST(SAF03_NoHeap, CycleNeverAllocates) {
  SafetyService s{Config{}};
  std::mt19937 rng(7);
  std::uint8_t junk[80];
  std::array<Encoded, 5> valid{encode(clear()), encode(pressed()), encode(health(Health::Fatal)), encode(accepted()),
                               encode(taken_by_other())};
  g_on = true;
  for (int i = 0; i < 100000; ++i) {
    InboundBatch b{};
    const unsigned k = rng() % 6;
    for (unsigned j = 0; j < k; ++j) {
      if (rng() % 3 == 0) {
        for (std::uint8_t& x : junk) x = static_cast<std::uint8_t>(rng());
        (void)b.push(junk, 1 + rng() % sizeof junk);
      } else {
        const std::size_t v = rng() % valid.size();
        (void)b.push(valid[v], v < 2 ? Sender::Client : Sender::Subsystem);
      }
    }
    (void)s.cycle(b, rng() % 50000 == 0);
  }
  g_on = false;
  EXPECT_EQ(g_news.load(), 0);
  EXPECT_GT(s.diagnostics().rejected_total(), 0U);
  EXPECT_GT(s.diagnostics().accepted, 0U);
}

TEST(SAF03_NoHeap, HostCycleWithTheLinkKeyNeverAllocates) {
  HostRig r(true);
  const Encoded forged = encode(Message::report_health(Health::Normal));
  g_on = true;
  for (int i = 0; i < 400; ++i) {
    r.client->set_mode(i % 100 < 50 ? ClientMode::Clear : ClientMode::Emergency);
    r.send(forged);
    (void)r.cycle();
  }
  g_on = false;
  EXPECT_EQ(g_news.load(), 0);
  EXPECT_GT(r.host->intake().counters().accepted, 400U);
  EXPECT_GT(r.host->sequences().service, 1U);  // sealed messages went out
}

}  // namespace
}  // namespace safestate::saf::test
