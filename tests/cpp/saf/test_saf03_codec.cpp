// SPDX-License-Identifier: Apache-2.0
// SAF-03: the nine message ids, the wire format of design §10, and every malformed,
// truncated, oversized or unknown datagram rejected with its reason, counted, and
// changing nothing else.
#include <vector>

#include "saf_test_support.hpp"

namespace safestate::saf::test {
namespace {

std::vector<std::uint8_t> bytes_of(const Message& m) {
  const Encoded e = encode(m);
  return {e.bytes.begin(), e.bytes.begin() + static_cast<std::ptrdiff_t>(e.size)};
}

DecodeError error_of(const std::vector<std::uint8_t>& b) { return decode(b.data(), b.size()).error; }

TEST(SAF03_Ids, SeedIdsWithHighWordOne) {
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::SetEstop), 0x000000010000013CULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::ReportHealthSummary), 0x000000010000013EULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::ConfirmControl), 0x000000010000012DULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::ReportControl), 0x000000010000012FULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::ReportSubsystemState), 0x000000010000013BULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::QueryHealthSummary), 0x000000010000013DULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::RequestControl), 0x000000010000012AULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::QueryControl), 0x000000010000012CULL);
  EXPECT_EQ(static_cast<std::uint64_t>(MessageId::SetSubsystemState), 0x0000000100000139ULL);
}

TEST(SAF03_Codec, LittleEndianLayoutOfSetEstop) {
  EXPECT_EQ(bytes_of(pressed()), (std::vector<std::uint8_t>{0x3C, 0x01, 0, 0, 0x01, 0, 0, 0, 0x01, 0x00, 0x01}));
  EXPECT_EQ(bytes_of(Message::request_control(ControlAction::Request, 225, 0x01020304)),
            (std::vector<std::uint8_t>{0x2A, 0x01, 0, 0, 0x01, 0, 0, 0, 0x06, 0x00, 0, 225, 4, 3, 2, 1}));
}

TEST(SAF03_Codec, EveryTypeRoundTrips) {
  const Message all[] = {pressed(),
                         clear(),
                         health(Health::Fatal),
                         refused(),
                         accepted(),
                         Message::report_control(0xDEADBEEF, 200),
                         Message::report_subsystem_state(SubsystemState::Failure),
                         Message::query(MessageId::QueryHealthSummary),
                         Message::request_control(ControlAction::Release, 225, 77),
                         Message::query(MessageId::QueryControl),
                         Message::set_subsystem_state(SubsystemState::Emergency)};
  for (const Message& m : all) {
    const Encoded e = encode(m);
    const DecodeResult r = decode(e.bytes.data(), e.size);
    ASSERT_TRUE(r.ok()) << to_string(r.error);
    EXPECT_EQ(r.message.id, m.id);
    EXPECT_EQ(encode(r.message).size, e.size);
    EXPECT_EQ(encode(r.message).bytes, e.bytes);
  }
}

TEST(SAF03_Malformed, Truncated) {
  std::vector<std::uint8_t> b = bytes_of(pressed());
  for (std::size_t n = 0; n < b.size(); ++n) {
    EXPECT_EQ(error_of({b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n)}), DecodeError::Truncated) << n;
  }
  EXPECT_EQ(decode(nullptr, 0).error, DecodeError::Truncated);
}

TEST(SAF03_Malformed, Oversized) {
  std::vector<std::uint8_t> b(kMaxDatagram + 1, 0);
  EXPECT_EQ(error_of(b), DecodeError::Oversized);
}

TEST(SAF03_Malformed, TrailingBytes) {
  std::vector<std::uint8_t> b = bytes_of(pressed());
  b.push_back(0);
  EXPECT_EQ(error_of(b), DecodeError::TrailingBytes);
}

TEST(SAF03_Malformed, UnknownIdLowOrHighWord) {
  std::vector<std::uint8_t> b = bytes_of(pressed());
  b[0] = 0x3F;  // 0x13F: not one of the nine
  EXPECT_EQ(error_of(b), DecodeError::UnknownId);
  b = bytes_of(pressed());
  b[4] = 0x02;  // high word 2
  EXPECT_EQ(error_of(b), DecodeError::UnknownId);
}

TEST(SAF03_Malformed, LengthFieldDiffersFromTheType) {
  std::vector<std::uint8_t> b = bytes_of(pressed());
  b[8] = 2;
  b.push_back(0);
  EXPECT_EQ(error_of(b), DecodeError::BadLength);
}

TEST(SAF03_Malformed, FieldOutOfRange) {
  struct Case {
    Message m;
    std::size_t offset;
    std::uint8_t value;
  };
  const Case cases[] = {{pressed(), 10, 2},
                        {health(Health::Normal), 10, 4},
                        {accepted(), 10, 3},
                        {Message::report_subsystem_state(SubsystemState::Initialize), 10, 4},
                        {Message::request_control(ControlAction::Request, 225, 1), 10, 2},
                        {Message::set_subsystem_state(SubsystemState::Emergency), 10, 0xFF}};
  for (const Case& c : cases) {
    std::vector<std::uint8_t> b = bytes_of(c.m);
    b[c.offset] = c.value;
    EXPECT_EQ(error_of(b), DecodeError::FieldRange) << spec_of(c.m.id).name;
  }
}

TEST(SAF03_Service, OutgoingTypesAreRejectedAsNotIncoming) {
  SafetyService s{kSmall, 225};
  (void)run(s, {Message::query(MessageId::QueryControl), Message::set_subsystem_state(SubsystemState::Operational)});
  EXPECT_EQ(s.diagnostics().rejected[static_cast<std::size_t>(DecodeError::NotIncoming)], 2U);
  EXPECT_EQ(s.diagnostics().accepted, 0U);
}

TEST(SAF03_Service, RejectedDatagramsChangeNothingButTheirCounter) {
  SafetyService a = operational();
  SafetyService b = operational();
  std::vector<std::vector<std::uint8_t>> garbage = {{}, {1}, std::vector<std::uint8_t>(100, 0xFF), bytes_of(pressed())};
  garbage[3][10] = 7;  // FIELD_RANGE, an emergency flag of 7
  for (int i = 0; i < 2; ++i) {
    InboundBatch with{};
    ASSERT_TRUE(with.push(encode(clear()), Sender::Client));
    for (const auto& g : garbage) ASSERT_TRUE(with.push(g.data(), g.size()));
    const CycleResult ra = a.cycle(with, false);
    const CycleResult rb = run(b, {clear()});
    EXPECT_EQ(a.observe(), b.observe());
    EXPECT_EQ(ra.outbox.count, rb.outbox.count);
  }
  EXPECT_EQ(a.diagnostics().rejected_total(), 8U);
  EXPECT_EQ(a.diagnostics().rejected[static_cast<std::size_t>(DecodeError::Oversized)], 2U);
  EXPECT_EQ(a.diagnostics().rejected[static_cast<std::size_t>(DecodeError::FieldRange)], 2U);
}

TEST(SAF03_Service, LastMessageOfEachKindInACycleWins) {
  SafetyService s = operational();
  (void)run(s, {pressed(), clear()});
  EXPECT_EQ(s.observe().state, SafState::Operational);
  (void)run(s, {clear(), pressed()});
  EXPECT_EQ(s.observe().state, SafState::Emergency);
}

}  // namespace
}  // namespace safestate::saf::test
