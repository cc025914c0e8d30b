// SPDX-License-Identifier: Apache-2.0
// The transition table itself: row ids and order, well-formedness, agreement with the
// design page (docs/design/system-state-manager.md §5/§6/§7), and the JSON/DOT exports.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "safestate/transition_table.hpp"
#include "safestate/transition_table_export.hpp"

namespace {

using namespace safestate;  // NOLINT

std::string two_digits(std::size_t n) { return (n < 10 ? "0" : "") + std::to_string(n); }

// Rows added by later changes take the next free number and sit where first-match needs
// them: C24 (fieldbus loss) after C03, C25 (standstill) after C10, C26 (operator link) after C14, K36 after K02, K37
// after K04, K38 after K06.
TEST(TransitionTable, RowIdsAreC01ToC30ThenK01ToK39InFirstMatchOrder) {
  // The latching rows C09, C27, C10, C29, C25 precede the E-stop's C06 (issue 29 item 7);
  // C30 (feedback) follows C24 and precedes every row that reads a free signal.
  std::vector<std::string> expected{"C01", "C02", "C03", "C24", "C30", "C04", "C05", "C09", "C27", "C10",
                                    "C29", "C25", "C06", "C07", "C08", "C11", "C12", "C13", "C14", "C26",
                                    "C15", "C16", "C17", "C18", "C28", "C19", "C20", "C21", "C22", "C23"};
  for (std::size_t i = 1; i <= 35; ++i) {
    expected.push_back("K" + two_digits(i));
    if (i == 2) expected.emplace_back("K36");
    if (i == 4) expected.emplace_back("K37");
    if (i == 6) expected.emplace_back("K38");
    if (i == 10) expected.emplace_back("K39");
  }
  ASSERT_EQ(kTransitionTable.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(kTransitionTable[i].id, expected[i]);
  EXPECT_TRUE(table_check::ids_unique());
}

TEST(TransitionTable, EveryRejectRowHasAReasonAndOnlyCommandRowsReject) {
  for (const TransitionRow& r : kTransitionTable) {
    if (r.kind == TargetKind::Reject) {
      EXPECT_NE(r.reason, RejectReason::None) << r.id;
      EXPECT_NE(r.event, RowEvent::Cycle) << r.id;
    } else {
      EXPECT_EQ(r.reason, RejectReason::None) << r.id;
    }
  }
}

TEST(TransitionTable, EffectiveSourcesFollowFromFirstMatch) {
  EXPECT_EQ(effective_source(row_index("K05")), StateSet{StateId::EstopResetNeeded});
  EXPECT_EQ(effective_source(row_index("K12")), StateSet{StateId::Idle});
  EXPECT_EQ(effective_source(row_index("K18")), StateSet{StateId::AutoIdle});
  EXPECT_EQ(effective_source(row_index("C06")),
            StateSet::all_except({StateId::EstopActive, StateId::ErrorLockout, StateId::Boot}));
  EXPECT_EQ(effective_source(row_index("C01")), StateSet{StateId::ErrorLockout});
}

// §7 and the RSM-03 table: which rows set which stop category.
TEST(RSM03_StopCategories, TheTableSetsTheCategoriesOfTheDesignTriggerTable) {
  const std::map<std::string, StopUpdate> expected{
      {"C02", StopUpdate::Cat0}, {"C03", StopUpdate::Cat0}, {"C04", StopUpdate::Cat0}, {"C06", StopUpdate::Cat0},
      {"C09", StopUpdate::Cat0}, {"C10", StopUpdate::Cat0}, {"C11", StopUpdate::Cat0}, {"C12", StopUpdate::Cat1},
      {"C13", StopUpdate::Cat1}, {"C14", StopUpdate::Cat1}, {"C16", StopUpdate::Cat0}, {"C20", StopUpdate::Cat0},
      {"C24", StopUpdate::Cat0}, {"C25", StopUpdate::Cat0}, {"C26", StopUpdate::Cat2}, {"K12", StopUpdate::Clear},
      {"K14", StopUpdate::Cat1}, {"K20", StopUpdate::Cat2}, {"C27", StopUpdate::Cat0}, {"K32", StopUpdate::Cat2},
      {"C29", StopUpdate::Cat0}, {"C30", StopUpdate::Cat0},
  };
  for (const TransitionRow& r : kTransitionTable) {
    const auto it = expected.find(std::string(r.id));
    EXPECT_EQ(r.stop, it == expected.end() ? StopUpdate::Keep : it->second) << r.id;
  }
}

// ---- agreement with the design page ----------------------------------------------------

std::string trim(std::string s) {
  while (!s.empty() && (s.front() == ' ')) s.erase(s.begin());
  while (!s.empty() && (s.back() == ' ')) s.pop_back();
  return s;
}

/// Cells of the page's table rows "| C01 | ... |" / "| K01 | ... |", by row id.
std::map<std::string, std::vector<std::string>> design_rows() {
  std::ifstream f(std::string(SAFESTATE_SOURCE_DIR) + "/docs/design/system-state-manager.md");
  std::map<std::string, std::vector<std::string>> rows;
  std::string line;
  while (std::getline(f, line)) {
    if (line.size() < 7 || line.rfind("| ", 0) != 0) continue;
    if ((line[2] != 'C' && line[2] != 'K') || !isdigit(line[3]) || !isdigit(line[4]) || line[5] != ' ') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line.substr(1));
    std::string cell;
    while (std::getline(ss, cell, '|')) cells.push_back(trim(cell));
    if (!cells.empty() && cells.back().empty()) cells.pop_back();
    rows[cells[0]] = cells;
  }
  return rows;
}

TEST(TransitionTable, RowsMatchTheDesignPage) {
  const auto page = design_rows();
  ASSERT_EQ(page.size(), kTransitionTable.size()) << "the page's §5/§6 tables were not found";
  for (const TransitionRow& r : kTransitionTable) {
    const auto it = page.find(std::string(r.id));
    ASSERT_NE(it, page.end()) << r.id;
    const std::vector<std::string>& cells = it->second;
    ASSERT_EQ(cells.size(), 5U) << r.id;
    // Requirement column.
    const std::string reqs = cells[4] == "—" ? "-" : cells[4];
    EXPECT_EQ(std::string(r.requirements), reqs) << r.id;
    if (r.id[0] == 'K') {
      // Command column.
      const std::string& cmd = cells[1];
      if (cmd == "any") {
        EXPECT_EQ(r.event, RowEvent::AnyCommand) << r.id;
      } else {
        EXPECT_EQ(cmd.rfind(std::string(to_string(r.event)), 0), 0U) << r.id << ": " << cmd;
      }
      // Reason column: a single `REASON` is a reject row with that reason.
      const std::string& effect = cells[3];
      const bool is_reason =
          effect.size() > 2 && effect.front() == '`' && effect.back() == '`' && effect.find(' ') == std::string::npos;
      if (is_reason) {
        EXPECT_EQ(r.kind, TargetKind::Reject) << r.id;
        EXPECT_EQ("`" + std::string(to_string(r.reason)) + "`", effect) << r.id;
      } else {
        EXPECT_NE(r.kind, TargetKind::Reject) << r.id;
      }
    } else {
      // Stop category named in the target column.
      const std::string& target = cells[3];
      const StopUpdate stop = target.find("CAT0") != std::string::npos   ? StopUpdate::Cat0
                              : target.find("CAT1") != std::string::npos ? StopUpdate::Cat1
                              : target.find("CAT2") != std::string::npos ? StopUpdate::Cat2
                                                                         : StopUpdate::Keep;
      EXPECT_EQ(r.stop, stop) << r.id;
      const bool stays = target.rfind("stay", 0) == 0 || target.rfind("`", 0) == 0 || target == "no change";
      EXPECT_EQ(r.kind == TargetKind::Stay, stays) << r.id << ": " << target;
      if (r.kind == TargetKind::Enter) {
        for (const StateId s : kAllStates) {
          if (r.targets.contains(s)) {
            EXPECT_NE(target.find(std::string(to_string(s))), std::string::npos) << r.id << " " << to_string(s);
          }
        }
      }
    }
  }
}

// ---- exports -----------------------------------------------------------------------------

std::size_t count(const std::string& haystack, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t pos = haystack.find(needle); pos != std::string::npos; pos = haystack.find(needle, pos + 1)) ++n;
  return n;
}

TEST(TransitionTableExport, JsonListsEveryRowOnceInOrder) {
  const std::string json = to_json();
  EXPECT_EQ(count(json, "\"id\": "), kTransitionTable.size());
  std::size_t last = 0;
  for (const TransitionRow& r : kTransitionTable) {
    const std::string key = "\"id\": \"" + std::string(r.id) + "\"";
    EXPECT_EQ(count(json, key), 1U) << r.id;
    const std::size_t pos = json.find(key);
    EXPECT_GT(pos, last) << r.id;
    last = pos;
  }
  EXPECT_EQ(json.find("QUEUE_FULL"), std::string::npos);  // not a table row
  EXPECT_NE(json.find("\"guard\": \"selector_differs_from_session_unless_cat1_stopping\""), std::string::npos);
  EXPECT_NE(json.find("\"requirements\": [\"RSM-05\", \"INV-RESET\"]"), std::string::npos);
  EXPECT_EQ(json.front(), '{');
  EXPECT_EQ(json.substr(json.size() - 3), "]}\n");
}

// The operator panel parses this JSON (python/safestate/panel/diagram_dot.py): each row is
// one object on its own line, its fields separated by ", ".  Checked on whole rows, since a
// search for one field still finds it when the separator before it or a name is missing.
TEST(TransitionTableExport, JsonRowsAreWholeObjectsWithEveryFieldSeparated) {
  const std::string json = to_json();
  EXPECT_NE(json.find("\n  {\"id\": \"C01\", \"section\": \"cycle\", \"event\": \"CYCLE\", \"source\": "
                      "[\"ERROR_LOCKOUT\"], \"effective_source\": [\"ERROR_LOCKOUT\"], \"guard\": \"always\", "
                      "\"kind\": \"STAY\", \"targets\": [], \"reason\": \"NONE\", \"stop_category\": \"KEEP\", "
                      "\"action\": \"none\", \"requirements\": [\"RSM-04\", \"INV-DISCREPANCY\"]},\n"),
            std::string::npos);
  std::istringstream lines(json);
  std::size_t rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  {\"id\": ", 0) != 0) continue;
    ++rows;
    for (const char* key : {"section", "event", "source", "effective_source", "guard", "kind", "targets", "reason",
                            "stop_category", "action", "requirements"}) {
      EXPECT_NE(line.find(std::string(", \"") + key + "\": "), std::string::npos) << key << " in " << line;
    }
  }
  EXPECT_EQ(rows, kTransitionTable.size());
}

// The names the design page's tables and the exports use for a row's kind and its effect
// on stop_category (§5-§7; Clear is K12's reset of the category to NONE).
TEST(RSM03_StopCategories, RowKindAndStopUpdateNamesAreThoseOfTheDesignPage) {
  EXPECT_EQ(to_string(StopUpdate::Keep), "KEEP");
  EXPECT_EQ(to_string(StopUpdate::Cat0), "CAT0");
  EXPECT_EQ(to_string(StopUpdate::Cat1), "CAT1");
  EXPECT_EQ(to_string(StopUpdate::Cat2), "CAT2");
  EXPECT_EQ(to_string(StopUpdate::Clear), "NONE");
  EXPECT_EQ(to_string(TargetKind::Enter), "ENTER");
  EXPECT_EQ(to_string(TargetKind::Stay), "STAY");
  EXPECT_EQ(to_string(TargetKind::Reject), "REJECT");
}

TEST(TransitionTableExport, DotListsEveryRowAndEveryState) {
  const std::string dot = to_dot();
  EXPECT_EQ(dot.rfind("digraph SystemStateManager {", 0), 0U);
  for (const TransitionRow& r : kTransitionTable) {
    EXPECT_NE(dot.find(std::string(r.id) + " "), std::string::npos) << r.id;
  }
  for (const StateId s : kAllStates) EXPECT_NE(dot.find("  " + std::string(to_string(s))), std::string::npos);
  EXPECT_NE(dot.find("IDLE -> ARMING [label=\"K12 SERVO_ON / NONE\"]"), std::string::npos);
  EXPECT_NE(dot.find("ESTOP_RESET_NEEDED -> IDLE [label=\"K05 RESET\"]"), std::string::npos);
}

}  // namespace
