// SCH-01..SCH-04: the state-chain engine on the seed document's Figure 4 tree
// (docs/design/state-chain.md; the same tree as models/StateChainDoc.tla).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "safestate/chain/chain_export.hpp"
#include "safestate/chain/state_chain.hpp"

namespace sc = safestate::chain;

namespace {

struct Log {
  std::array<std::string, 64> events{};
  std::size_t size = 0;
  sc::StateIndex request_src = sc::no_state, request_dst = sc::no_state;  // made by S3's run
  std::string joined() const {
    std::string s;
    for (std::size_t i = 0; i < size; ++i) s += (i ? " " : "") + events[i];
    return s;
  }
};

// Indices in pre-order: S0 S1 SA S3 S4 SY S7 SZ S8 SB S5 S6 S2.
enum : sc::StateIndex { S0, S1, SA, S3, S4, SY, S7, SZ, S8, SB, S5, S6, S2 };
constexpr const char* names[] = {"S0", "S1", "SA", "S3", "S4", "SY", "S7", "SZ", "S8", "SB", "S5", "S6", "S2"};

template <sc::StateIndex S>
void entry(Log& l, const sc::Requests&) noexcept {
  l.events[l.size++] = std::string(names[S]) + "_init";
}
template <sc::StateIndex S>
void exit_(Log& l, const sc::Requests&) noexcept {
  l.events[l.size++] = std::string(names[S]) + "_del";
}
template <sc::StateIndex S>
void run(Log& l, const sc::Requests& r) noexcept {
  l.events[l.size++] = std::string(names[S]) + "_run";
  if (S == S3 && l.request_src != sc::no_state) static_cast<void>(r.request(l.request_src, l.request_dst));
}

template <sc::StateIndex S>
constexpr sc::StateDef<Log> def(sc::StateIndex parent, sc::StateIndex initial, bool parallel) {
  return {names[S], parent, initial, parallel, &entry<S>, &exit_<S>, &run<S>, nullptr};
}

constexpr std::array<sc::StateDef<Log>, 13> doc_table{
    {def<S0>(sc::no_state, S1, false), def<S1>(S0, sc::no_state, true), def<SA>(S1, S3, false),
     def<S3>(SA, sc::no_state, false), def<S4>(SA, sc::no_state, true), def<SY>(S4, S7, false),
     def<S7>(SY, sc::no_state, false), def<SZ>(S4, S8, false), def<S8>(SZ, sc::no_state, false), def<SB>(S1, S5, false),
     def<S5>(SB, sc::no_state, false), def<S6>(SB, sc::no_state, false), def<S2>(S0, sc::no_state, false)}};
static_assert(sc::check_table(doc_table).ok());

struct DocChain : ::testing::Test {
  Log log;
  sc::StateChain<Log, 13> chain{doc_table, log};
  std::string active() const {
    std::string s;
    for (sc::StateIndex i = 0; i < 13; ++i) {
      if (chain.is_active(i)) s += (s.empty() ? "" : " ") + std::string(names[i]);
    }
    return s;
  }
  void clear() { log.size = 0; }
};

TEST_F(DocChain, SCH01_PowerUpActivatesRootDownToLeavesTopDown) {
  chain.start();
  EXPECT_EQ(active(), "S0 S1 SA S3 SB S5");
  EXPECT_EQ(log.joined(), "S0_init S1_init SA_init S3_init SB_init S5_init");
}

TEST_F(DocChain, SCH01_ExitIsLeafFirstBottomUpIncludingNestedSubChains) {
  chain.start();
  ASSERT_EQ(chain.request(S3, S4), sc::RequestResult::ok);
  EXPECT_EQ(active(), "S0 S1 SA S4 SY S7 SZ S8 SB S5");
  clear();
  ASSERT_EQ(chain.request(S1, S2), sc::RequestResult::ok);
  EXPECT_EQ(log.joined(), "S5_del SB_del S8_del SZ_del S7_del SY_del S4_del SA_del S1_del S2_init");
  EXPECT_EQ(active(), "S0 S2");
}

TEST_F(DocChain, SCH02_CrossLevelRequestIsRejectedAndChangesNothing) {
  chain.start();
  clear();
  EXPECT_EQ(chain.request(S3, S6), sc::RequestResult::cross_level);
  EXPECT_EQ(chain.request(S5, S2), sc::RequestResult::cross_level);
  EXPECT_EQ(log.size, 0U);
  EXPECT_EQ(active(), "S0 S1 SA S3 SB S5");
}

TEST_F(DocChain, SCH02_RequestToActiveSiblingOrFromInactiveOrUnknownIsRejected) {
  chain.start();
  EXPECT_EQ(chain.request(SA, SB), sc::RequestResult::target_active);
  EXPECT_EQ(chain.request(S6, S5), sc::RequestResult::source_inactive);
  EXPECT_EQ(chain.request(S3, 13), sc::RequestResult::unknown_state);
  EXPECT_EQ(active(), "S0 S1 SA S3 SB S5");
}

TEST_F(DocChain, SCH02_SelfTransitionExitsAndReentersToTheInitialLeaf) {
  chain.start();
  ASSERT_EQ(chain.request(S5, S6), sc::RequestResult::ok);
  clear();
  ASSERT_EQ(chain.request(SB, SB), sc::RequestResult::ok);
  EXPECT_EQ(log.joined(), "S6_del SB_del SB_init S5_init");
  EXPECT_EQ(active(), "S0 S1 SA S3 SB S5");
}

TEST_F(DocChain, SCH03_ParallelSubChainsStartAndExitWithTheirState) {
  chain.start();
  EXPECT_TRUE(chain.is_active(SA) && chain.is_active(SB));
  ASSERT_EQ(chain.request(S1, S2), sc::RequestResult::ok);
  EXPECT_FALSE(chain.is_active(SA) || chain.is_active(SB) || chain.is_active(S5));
  ASSERT_EQ(chain.request(S2, S1), sc::RequestResult::ok);
  EXPECT_EQ(active(), "S0 S1 SA S3 SB S5");
}

TEST_F(DocChain, SCH04_ScanRunsActiveStatesLeafToRootPerSubChain) {
  chain.start();
  ASSERT_EQ(chain.request(S3, S4), sc::RequestResult::ok);
  clear();
  chain.run();
  EXPECT_EQ(log.joined(), "S5_run SB_run S8_run SZ_run S7_run SY_run S4_run SA_run S1_run S0_run");
}

TEST_F(DocChain, SCH04_StatesExitedByARunRequestAreNotRunInThatScan) {
  chain.start();
  log.request_src = S3;  // S3's run requests S3 -> S4 (the document's S3_Run)
  log.request_dst = S4;
  clear();
  chain.run();
  EXPECT_EQ(log.joined(), "S5_run SB_run S3_run S3_del S4_init SY_init S7_init SZ_init S8_init SA_run S1_run S0_run");
}

TEST(StateChainTable, RejectsATableNotInPreOrderOrWithABadInitialChild) {
  auto bad = doc_table;
  bad[S0].initial = S3;  // not a child of S0
  EXPECT_EQ(sc::check_table(bad).error, sc::TableError::bad_initial);
  auto out_of_order = doc_table;
  out_of_order[SA].parent = S2;  // parent after its child
  EXPECT_EQ(sc::check_table(out_of_order).error, sc::TableError::parent_not_before);
  auto interrupted = doc_table;
  interrupted[S2].parent = SA;  // SA's subtree interrupted by SB
  EXPECT_EQ(sc::check_table(interrupted).error, sc::TableError::subtree_not_contiguous);
}

TEST(StateChainExport, JsonAndDotNameEveryStateAndEdge) {
  const std::string json = sc::to_json(doc_table);
  EXPECT_NE(json.find("{\"name\": \"S4\", \"parent\": \"SA\", \"initial\": null, \"parallel\": true}"),
            std::string::npos);
  const std::string dot = sc::to_dot(doc_table);
  EXPECT_NE(dot.find("\"S0\" -> \"S1\" [style=bold];"), std::string::npos);
  EXPECT_NE(dot.find("\"S1\" [peripheries=2];"), std::string::npos);
}

}  // namespace
