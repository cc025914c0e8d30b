// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 10: the CiA 402 status word of each drive (IEC 61800-7-201) decoded in the
// core and reduced to servo_ready / drive_fault (design §2 "Drive status words").
#include <gtest/gtest.h>

#include <cstdint>

#include "safestate/cia402_status_word.hpp"
#include "safestate/drive_status_summary.hpp"

namespace {

using namespace safestate;  // NOLINT: test code

// The example words of the standard's state table, with the don't-care bits both ways.
TEST(Issue29_Item10_Cia402, EachStateOfTheStandardsTableIsDecoded) {
  struct Case {
    std::uint16_t word;
    Cia402State state;
  };
  const Case cases[] = {
      {0x0000, Cia402State::NotReadyToSwitchOn},  {0x0040, Cia402State::SwitchOnDisabled},
      {0x0021, Cia402State::ReadyToSwitchOn},     {0x0023, Cia402State::SwitchedOn},
      {0x0027, Cia402State::OperationEnabled},    {0x0007, Cia402State::QuickStopActive},
      {0x000F, Cia402State::FaultReactionActive}, {0x0008, Cia402State::Fault},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(cia402_state(c.word), c.state) << std::hex << c.word;
    // Bits the pattern does not read (voltage enabled, warning, remote, target reached,
    // manufacturer bits) do not change the state.
    const auto others = static_cast<std::uint16_t>(c.word | 0xFF90U);
    const std::uint16_t mask = c.state == Cia402State::NotReadyToSwitchOn || c.state == Cia402State::SwitchOnDisabled ||
                                       c.state == Cia402State::FaultReactionActive || c.state == Cia402State::Fault
                                   ? 0x004F
                                   : 0x006F;
    EXPECT_EQ(cia402_state(static_cast<std::uint16_t>((others & ~mask) | c.word)), c.state) << std::hex << others;
  }
}

TEST(Issue29_Item10_Cia402, AWordMatchingNoStateIsInvalidAndCountsAsAFault) {
  // Ready to switch on with the quick stop bit clear (x00x 0001) is not in the table.
  EXPECT_EQ(cia402_state(0x0001), Cia402State::Invalid);
  EXPECT_EQ(cia402_state(0x0047), Cia402State::Invalid);  // switch on disabled with bits 0-2 set
  EXPECT_TRUE(is_faulted(decode_status_word(0x0001)));
  int invalid = 0;
  for (std::uint32_t w = 0; w < 0x80U; ++w) {
    if (cia402_state(static_cast<std::uint16_t>(w)) == Cia402State::Invalid) ++invalid;
  }
  EXPECT_GT(invalid, 0);
}

TEST(Issue29_Item10_Cia402, FlagBitsAreReportedBesideTheState) {
  const DriveStatus d = decode_status_word(0x00B7);  // operation enabled, voltage, warning
  EXPECT_EQ(d.state, Cia402State::OperationEnabled);
  EXPECT_TRUE(d.warning);
  EXPECT_TRUE(d.voltage_enabled);
  EXPECT_FALSE(d.quick_stop);  // bit 5 set: no quick stop
  const DriveStatus q = decode_status_word(0x0017);
  EXPECT_EQ(q.state, Cia402State::QuickStopActive);
  EXPECT_TRUE(q.quick_stop);
  EXPECT_FALSE(is_faulted(q));
  EXPECT_FALSE(is_operation_enabled(q));
}

TEST(Issue29_Item10_Cia402, ServoReadyNeedsEveryDriveOperationEnabled) {
  DriveStatusWords w{};
  w.fill(0x0037);
  EXPECT_TRUE(summarize_drives(w).servo_ready);
  EXPECT_FALSE(summarize_drives(w).drive_fault);
  for (std::size_t i = 0; i < w.size(); ++i) {
    DriveStatusWords one = w;
    one[i] = 0x0033;  // switched on, not yet enabled
    EXPECT_FALSE(summarize_drives(one).servo_ready) << "drive " << i;
    one[i] = 0x0017;  // quick stop: not ready, not a fault
    EXPECT_FALSE(summarize_drives(one).servo_ready) << "drive " << i;
    EXPECT_FALSE(summarize_drives(one).drive_fault) << "drive " << i;
  }
}

TEST(Issue29_Item10_Cia402, AnyDriveInFaultIsADriveFault) {
  DriveStatusWords w{};
  w.fill(0x0037);
  for (const std::uint16_t bad : {std::uint16_t{0x0008}, std::uint16_t{0x001F}, std::uint16_t{0x0001}}) {
    for (std::size_t i = 0; i < w.size(); ++i) {
      DriveStatusWords one = w;
      one[i] = bad;
      const DriveStatusSummary s = summarize_drives(one);
      EXPECT_TRUE(s.drive_fault) << std::hex << bad << " on drive " << i;
      EXPECT_FALSE(s.servo_ready) << std::hex << bad << " on drive " << i;
    }
  }
}

TEST(Issue29_Item10_Cia402, AWarningAloneIsNeitherAFaultNorLostReadiness) {
  DriveStatusWords w{};
  w.fill(0x0037);
  w[3] = 0x00B7;
  const DriveStatusSummary s = summarize_drives(w);
  EXPECT_TRUE(s.warning);
  EXPECT_TRUE(s.servo_ready);
  EXPECT_FALSE(s.drive_fault);
}

TEST(Issue29_Item10_Cia402, ZeroWordsReadNotReadyAndNoFault) {
  const DriveStatusSummary s = summarize_drives(DriveStatusWords{});
  EXPECT_FALSE(s.servo_ready);
  EXPECT_FALSE(s.drive_fault);
  for (const DriveStatus& d : s.drives) EXPECT_EQ(d.state, Cia402State::NotReadyToSwitchOn);
}

}  // namespace
