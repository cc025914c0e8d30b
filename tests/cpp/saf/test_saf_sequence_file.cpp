// SPDX-License-Identifier: Apache-2.0
// Issue 30, the replay window across a restart (design §15): the sequence file's store and
// load (0600, atomic, the exact format or a refusal naming the line), and the intake and
// the deployed service after a load: a Set Estop or a sealed subsystem message captured
// before the restart is stale after it.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "saf_host_rig.hpp"
#include "safestate/saf/sequence_file.hpp"

namespace safestate::saf::test {
namespace {

struct Folder {
  std::string path;
  Folder() {
    std::string t = "/tmp/saf_seq_XXXXXX";
    path = ::mkdtemp(t.data());
  }
  ~Folder() {
    for (const char* f : {"/saf.seq", "/saf.seq.tmp"}) ::unlink((path + f).c_str());
    ::rmdir(path.c_str());
  }
  [[nodiscard]] std::string file() const { return path + "/saf.seq"; }
};

void write_text(const std::string& path, const std::string& text, mode_t mode = 0600) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  ::chmod(path.c_str(), mode);
}

SequenceState some_state() {
  SequenceState s{};
  s.have_estop = true;
  s.estop = 1'733'150'000'123'456ULL;
  s.have_subsystem = true;
  s.subsystem = 18'446'744'073'709'551'615ULL;  // the largest u64 round-trips
  s.service = 42;
  return s;
}

TEST(SAF_SequenceFile, StoreThenLoadGivesTheSameStateInAFileOnlyItsOwnerCanRead) {
  const Folder f;
  const SequenceFileResult w = store_sequence_file(f.file().c_str(), some_state());
  ASSERT_EQ(w.error, SequenceFileError::None) << w.error_number;
  struct stat st {};
  ASSERT_EQ(::stat(f.file().c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777U, 0600U);
  EXPECT_NE(::access((f.file() + ".tmp").c_str(), F_OK), 0);  // renamed, not left behind
  const SequenceFileResult r = load_sequence_file(f.file().c_str());
  ASSERT_EQ(r.error, SequenceFileError::None);
  EXPECT_EQ(r.state, some_state());

  SequenceState none{};
  none.service = 7;
  ASSERT_EQ(store_sequence_file(f.file().c_str(), none).error, SequenceFileError::None);  // replaces
  const SequenceFileResult r2 = load_sequence_file(f.file().c_str());
  ASSERT_EQ(r2.error, SequenceFileError::None);
  EXPECT_EQ(r2.state, none);
  EXPECT_FALSE(r2.state.have_estop);
}

TEST(SAF_SequenceFile, AMissingFileIsTheFirstStartNotAnError) {
  const Folder f;
  EXPECT_EQ(load_sequence_file(f.file().c_str()).error, SequenceFileError::Missing);
}

TEST(SAF_SequenceFile, ACorruptFileIsRefusedWithTheLineAndWhatWasExpected) {
  const Folder f;
  const std::string head = "safestate-saf-sequence 1\n";
  const struct {
    std::string text;
    std::size_t line;
  } cases[] = {
      {"", 1},
      {"safestate-saf-sequence 2\nestop 1\nsubsystem 1\nservice 1\n", 1},
      {head + "estop -1\nsubsystem 1\nservice 1\n", 2},
      {head + "estop 18446744073709551616\nsubsystem 1\nservice 1\n", 2},  // 2^64: overflow
      {head + "estop 007\nsubsystem 1\nservice 1\n", 2},
      {head + "estop 1\nsubsystem\nservice 1\n", 3},
      {head + "estop 1\nsubsystem 1\nservice none\n", 4},  // our own next sequence is never unknown
      {head + "estop 1\nsubsystem 1\nservice 1", 4},       // truncated: no newline
      {head + "estop 1\nsubsystem 1\nservice 1\nextra\n", 5},
      {head + "estop 1\r\nsubsystem 1\nservice 1\n", 2},
  };
  for (const auto& c : cases) {
    write_text(f.file(), c.text);
    const SequenceFileResult r = load_sequence_file(f.file().c_str());
    EXPECT_EQ(r.error, SequenceFileError::BadFormat) << c.text;
    EXPECT_EQ(r.line, c.line) << c.text;
    EXPECT_FALSE(r.expected.empty());
  }
  write_text(f.file(), head + std::string(200, '9'));
  EXPECT_EQ(load_sequence_file(f.file().c_str()).error, SequenceFileError::TooLong);
}

TEST(SAF_SequenceFile, AFileOthersCouldWriteOrADirectoryIsRefused) {
  const Folder f;
  ASSERT_EQ(store_sequence_file(f.file().c_str(), some_state()).error, SequenceFileError::None);
  ::chmod(f.file().c_str(), 0644);
  const SequenceFileResult r = load_sequence_file(f.file().c_str());
  EXPECT_EQ(r.error, SequenceFileError::Permissions);
  EXPECT_EQ(r.mode, 0644U);
  EXPECT_EQ(load_sequence_file(f.path.c_str()).error, SequenceFileError::NotRegular);
  // A store into a folder that does not exist says so (errno), it does not pretend.
  const SequenceFileResult w = store_sequence_file((f.path + "/no/such/saf.seq").c_str(), some_state());
  EXPECT_EQ(w.error, SequenceFileError::CannotWrite);
  EXPECT_EQ(w.error_number, ENOENT);
}

TEST(SAF_SequenceFile, TheIntakeAfterALoadRejectsWhatWasAcceptedBefore) {
  const Folder f;
  IntakeConfig c{};
  c.client = Peer{kLoopback, 4000};
  c.client_component_id = kClientId;
  c.subsystem = Peer{kLoopback, 4001};
  c.key = test_key();
  c.replay_window = 8;
  Intake before{c};
  const Encoded captured = encode_set_estop(false, kClientId, 1000, c.key);
  const Source client{c.client, SocketRole::Client};
  const Source subsystem{c.subsystem, SocketRole::Subsystem};
  auto datagram = [](const Encoded& e) {
    Datagram d{};
    d.size = e.size;
    for (std::size_t i = 0; i < e.size; ++i) d.bytes[i] = e.bytes[i];
    return d;
  };
  const Encoded report =
      link_seal(encode(Message::report_health(Health::Normal)), 500, LinkDirection::SubsystemToService, c.key);
  ASSERT_EQ(before.judge(datagram(captured), client, false).reason, IntakeReason::None);
  ASSERT_EQ(before.judge(datagram(report), subsystem, false).reason, IntakeReason::None);
  ASSERT_EQ(store_sequence_file(f.file().c_str(), before.sequences()).error, SequenceFileError::None);

  // A restart without the file: the capture is accepted once more (the gap the file closes).
  Intake forgetful{c};
  EXPECT_EQ(forgetful.judge(datagram(captured), client, false).reason, IntakeReason::None);

  Intake after{c};
  const SequenceFileResult loaded = load_sequence_file(f.file().c_str());
  ASSERT_EQ(loaded.error, SequenceFileError::None);
  after.restore(loaded.state);
  EXPECT_EQ(after.highest_sequence(), 1000U);
  EXPECT_EQ(after.judge(datagram(captured), client, false).reason, IntakeReason::EstopReplay);
  EXPECT_EQ(after.judge(datagram(encode_set_estop(false, kClientId, 992, c.key)), client, false).reason,
            IntakeReason::EstopStale);
  EXPECT_EQ(after.judge(datagram(report), subsystem, false).reason, IntakeReason::ReportReplay);
  EXPECT_EQ(after.judge(datagram(encode_set_estop(true, kClientId, 1001, c.key)), client, false).reason,
            IntakeReason::None);
  EXPECT_EQ(after
                .judge(datagram(link_seal(encode(Message::report_health(Health::Normal)), 501,
                                          LinkDirection::SubsystemToService, c.key)),
                       subsystem, false)
                .reason,
            IntakeReason::None);
}

HostConfig config_of(const HostRig& r) {
  HostConfig c{};
  c.intake.client = Peer{kLoopback, r.client->port()};
  c.intake.client_component_id = kClientId;
  c.intake.subsystem = Peer{kLoopback, r.subsystem->port()};
  c.intake.key = r.key;
  return c;
}

TEST(SAF_SequenceFile, ACapturedClearReplayedAfterARestartIsStaleAndTheSubsystemStaysEmergency) {
  const Folder f;
  HostRig r(true);
  r.client->set_mode(ClientMode::Clear);
  for (int i = 0; i < 60 && r.host->service().observe().state != SafState::Operational; ++i) r.cycle();
  ASSERT_EQ(r.host->service().observe().state, SafState::Operational);
  const Encoded captured = r.client->last_sent();
  r.client->set_mode(ClientMode::Emergency);
  for (int i = 0; i < 80; ++i) {
    r.cycle();
    ASSERT_EQ(store_sequence_file(f.file().c_str(), r.host->sequences()).error, SequenceFileError::None);
  }
  ASSERT_EQ(r.subsystem->state(), SubsystemState::Emergency);
  const std::uint64_t sent_before = r.host->sequences().service;

  // Restart: a new host on the same configuration, its replay state from the file.
  r.host.reset();
  HostConfig c = config_of(r);
  c.link_sequence_start = 1;  // a wall clock set back: the stored next sequence still wins
  r.host = std::make_unique<ServiceHost>(c);
  const SequenceFileResult loaded = load_sequence_file(f.file().c_str());
  ASSERT_EQ(loaded.error, SequenceFileError::None);
  r.host->restore(loaded.state);
  ASSERT_EQ(r.host->open(), HostError::None);
  EXPECT_GE(r.host->sequences().service, sent_before);

  for (int i = 0; i < 20; ++i) {
    r.client->send_raw(r.host->client_port(), captured);
    r.cycle();
    EXPECT_EQ(r.subsystem->state(), SubsystemState::Emergency) << "cycle " << i;
    EXPECT_NE(r.host->service().observe().state, SafState::Operational) << "cycle " << i;
  }
  EXPECT_EQ(r.host->intake().counters().of(IntakeReason::EstopStale), 20U);
  EXPECT_EQ(r.host->intake().counters().of(IntakeReason::EstopReplay), 0U);
  // The restarted service's sealed messages are fresh for the subsystem (none rejected).
  EXPECT_EQ(r.subsystem->rejected(LinkVerdict::Replay) + r.subsystem->rejected(LinkVerdict::Stale), 0U);
}

TEST(SAF_SequenceFile, AStoredValueAheadOfTheClientFailsSafe) {
  // A file whose Set Estop value is ahead of the client (a client whose counter went back):
  // every Set Estop is stale until the client passes it, so the restarted service never
  // hears a valid one and raises EMERGENCY as it does without a client.
  HostRig r(true);
  r.client->set_mode(ClientMode::Clear);
  for (int i = 0; i < 60 && r.host->service().observe().state != SafState::Operational; ++i) r.cycle();
  ASSERT_EQ(r.host->service().observe().state, SafState::Operational);
  SequenceState ahead = r.host->sequences();
  ahead.estop += 1'000'000;
  r.host.reset();
  r.host = std::make_unique<ServiceHost>(config_of(r));
  r.host->restore(ahead);
  ASSERT_EQ(r.host->open(), HostError::None);
  for (int i = 0; i < 40; ++i) r.cycle();
  // PAIRING raises EMERGENCY (P03) and never leaves it without a fresh Set Estop.
  EXPECT_NE(r.host->service().observe().state, SafState::Operational);
  EXPECT_EQ(r.subsystem->state(), SubsystemState::Emergency);
  EXPECT_GE(r.host->intake().counters().of(IntakeReason::EstopStale), 39U);
}

}  // namespace
}  // namespace safestate::saf::test
