// SPDX-License-Identifier: Apache-2.0
// The Set Estop extension of design §14 on the wire: the layout of the sequenced and the
// authenticated form byte by byte, the MAC over bytes 0 .. 22, the decoded fields, and
// every other payload size still BAD_LENGTH.
#include <gtest/gtest.h>

#include "safestate/saf/estop_extension.hpp"

namespace safestate::saf::test {
namespace {

TEST(SAF03_EstopExtension, SequencedLayoutIsLittleEndian) {
  const Encoded e = encode_set_estop(true, 0x0A0B0C0D, 0x0102030405060708ULL, MacKey{});
  ASSERT_EQ(e.size, kHeaderSize + kEstopSequencedPayload);
  const std::uint8_t expected[] = {0x3C, 0x01, 0,    0,    0x01, 0, 0, 0,   // id
                                   13,   0,                                 // payload length
                                   1,                                       // emergency
                                   0x0D, 0x0C, 0x0B, 0x0A,                  // client id
                                   8,    7,    6,    5,    4,    3, 2, 1};  // sequence
  for (std::size_t i = 0; i < sizeof expected; ++i) EXPECT_EQ(e.bytes[i], expected[i]) << "byte " << i;
  const DecodeResult r = decode(e.bytes.data(), e.size);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.message.estop_form, EstopForm::Sequenced);
  EXPECT_TRUE(r.message.emergency);
  EXPECT_EQ(r.message.component_id, 0x0A0B0C0DU);
  EXPECT_EQ(r.message.sequence, 0x0102030405060708ULL);
}

TEST(SAF03_EstopExtension, AuthenticatedFormCarriesTheMacOfEverythingBeforeIt) {
  MacKey key{};
  key.size = 16;
  for (std::size_t i = 0; i < key.size; ++i) key.bytes[i] = static_cast<std::uint8_t>(0xA0 + i);
  const Encoded e = encode_set_estop(false, 7, 99, key);
  ASSERT_EQ(e.size, kHeaderSize + kEstopAuthenticatedPayload);
  EXPECT_EQ(e.bytes[8], kEstopAuthenticatedPayload);
  const Digest d = hmac_sha256(key.bytes.data(), key.size, e.bytes.data(), kEstopMacCovered);
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_EQ(e.bytes[kEstopMacCovered + i], d[i]);
  EXPECT_TRUE(estop_mac_valid(e.bytes.data(), e.size, key));
  EXPECT_FALSE(estop_mac_valid(e.bytes.data(), e.size, MacKey{}));
  const DecodeResult r = decode(e.bytes.data(), e.size);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.message.estop_form, EstopForm::Authenticated);
  EXPECT_EQ(r.message.sequence, 99U);
}

TEST(SAF03_EstopExtension, OtherPayloadSizesAreBadLength) {
  for (std::uint16_t n = 0; n <= kMaxDatagram - kHeaderSize; ++n) {
    Encoded e = encode(Message::set_estop(false));
    e.bytes[8] = static_cast<std::uint8_t>(n);
    e.size = kHeaderSize + n;
    const DecodeError got = decode(e.bytes.data(), e.size).error;
    const bool allowed = n == kEstopSeedPayload || n == kEstopSequencedPayload || n == kEstopAuthenticatedPayload;
    EXPECT_EQ(got, allowed ? DecodeError::None : DecodeError::BadLength) << "payload " << n;
  }
}

}  // namespace
}  // namespace safestate::saf::test
