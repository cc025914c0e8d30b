// SPDX-License-Identifier: Apache-2.0
// The SHA-256 / HMAC-SHA256 that authenticates Set Estop (design §14): the FIPS 180-4
// examples and every test case of RFC 4231, including keys longer than a block and a
// message fed in pieces that straddle block boundaries.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "safestate/saf/sha256.hpp"

namespace safestate::saf::test {
namespace {

std::string hex(const Digest& d, std::size_t n = kSha256Size) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    s += digits[d[i] >> 4U];
    s += digits[d[i] & 0xFU];
  }
  return s;
}

std::vector<std::uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }
std::vector<std::uint8_t> repeat(std::uint8_t b, std::size_t n) { return std::vector<std::uint8_t>(n, b); }

std::string sha(const std::vector<std::uint8_t>& m) { return hex(sha256(m.data(), m.size())); }
std::string mac(const std::vector<std::uint8_t>& k, const std::vector<std::uint8_t>& m, std::size_t n = 32) {
  return hex(hmac_sha256(k.data(), k.size(), m.data(), m.size()), n);
}

TEST(Issue30_Sha256, Fips180Examples) {
  EXPECT_EQ(sha(bytes("abc")), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha({}), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha(bytes("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha(repeat('a', 1000000)), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Issue30_Sha256, IncrementalEqualsOneShotAcrossBlockBoundaries) {
  const std::vector<std::uint8_t> m = repeat('q', 200);
  for (std::size_t cut : {1U, 55U, 56U, 63U, 64U, 65U, 119U, 128U}) {
    Sha256 s;
    s.update(m.data(), cut);
    s.update(m.data() + cut, m.size() - cut);
    EXPECT_EQ(hex(s.final()), sha(m)) << "cut at " << cut;
  }
}

TEST(Issue30_Sha256, Rfc4231HmacTestCases) {
  EXPECT_EQ(mac(repeat(0x0b, 20), bytes("Hi There")),
            "b0344c61d8db38535ca8afceaf0bf12b881dc200c9833da726e9376c2e32cff7");
  EXPECT_EQ(mac(bytes("Jefe"), bytes("what do ya want for nothing?")),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
  EXPECT_EQ(mac(repeat(0xaa, 20), repeat(0xdd, 50)),
            "773ea91e36800e46854db8ebd09181a72959098b3ef8c122d9635514ced565fe");
  std::vector<std::uint8_t> key4;
  for (std::uint8_t b = 1; b <= 25; ++b) key4.push_back(b);
  EXPECT_EQ(mac(key4, repeat(0xcd, 50)), "82558a389a443c0ea4cc819899f2083a85f0faa3e578f8077a2e3ff46729665b");
  EXPECT_EQ(mac(repeat(0x0c, 20), bytes("Test With Truncation"), 16), "a3b6167473100ee06e0c796c2955552b");
  EXPECT_EQ(mac(repeat(0xaa, 131), bytes("Test Using Larger Than Block-Size Key - Hash Key First")),
            "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54");
  EXPECT_EQ(mac(repeat(0xaa, 131), bytes("This is a test using a larger than block-size key and a larger than "
                                         "block-size data. The key needs to be hashed before being used by the "
                                         "HMAC algorithm.")),
            "9b09ffa71b942fcb27635fbcd5b0e944bfdc63644f0713938a7f51535c3a35e2");
}

TEST(Issue30_Sha256, MacEqualDetectsAnyDifferingByte) {
  Digest a = sha256(nullptr, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    Digest b = a;
    b[i] ^= 0x01U;
    EXPECT_FALSE(mac_equal(a.data(), b.data(), a.size())) << "byte " << i;
  }
  EXPECT_TRUE(mac_equal(a.data(), a.data(), a.size()));
}

}  // namespace
}  // namespace safestate::saf::test
