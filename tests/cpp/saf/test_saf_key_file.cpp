// SPDX-License-Identifier: Apache-2.0
// The HMAC key file of design §14: accepted only when group and others have no
// permission, as 32 to 128 hex digits; every other file refused with its reason.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "safestate/saf/key_file.hpp"

namespace safestate::saf::test {
namespace {

std::string write_key(const std::string& text, mode_t mode) {
  char path[] = "/tmp/saf_key_XXXXXX";
  const int fd = ::mkstemp(path);
  EXPECT_GE(fd, 0);
  EXPECT_EQ(::write(fd, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  ::close(fd);
  EXPECT_EQ(::chmod(path, mode), 0);
  return path;
}

const std::string kHex32 = "000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f";

TEST(Issue30_KeyFile, Mode0600HexKeyIsRead) {
  const std::string p = write_key(kHex32 + "\n", 0600);
  const KeyFileResult r = load_key_file(p.c_str());
  ::unlink(p.c_str());
  ASSERT_EQ(r.error, KeyFileError::None);
  ASSERT_EQ(r.key.size, 32U);
  EXPECT_EQ(r.key.bytes[0], 0x00);
  EXPECT_EQ(r.key.bytes[31], 0x1f);
}

TEST(Issue30_KeyFile, GroupOrOtherPermissionIsRefused) {
  for (mode_t mode : {0640, 0604, 0644, 0660, 0666}) {
    const std::string p = write_key(kHex32, mode);
    const KeyFileResult r = load_key_file(p.c_str());
    ::unlink(p.c_str());
    EXPECT_EQ(r.error, KeyFileError::Permissions) << std::oct << mode;
    EXPECT_EQ(r.mode, static_cast<std::uint32_t>(mode));
    EXPECT_FALSE(r.key.present());
  }
}

TEST(Issue30_KeyFile, ContentAndFileKindAreChecked) {
  const std::string not_hex = write_key(kHex32.substr(0, 62) + "zz", 0600);
  EXPECT_EQ(load_key_file(not_hex.c_str()).error, KeyFileError::NotHex);
  const std::string short_key = write_key(kHex32.substr(0, 30), 0600);
  EXPECT_EQ(load_key_file(short_key.c_str()).error, KeyFileError::BadLength);
  const std::string odd = write_key(kHex32.substr(0, 33), 0600);
  EXPECT_EQ(load_key_file(odd.c_str()).error, KeyFileError::BadLength);
  const std::string long_key = write_key(kHex32 + kHex32 + kHex32, 0600);
  EXPECT_EQ(load_key_file(long_key.c_str()).error, KeyFileError::BadLength);
  for (const std::string& p : {not_hex, short_key, odd, long_key}) ::unlink(p.c_str());
  EXPECT_EQ(load_key_file("/nonexistent/saf.key").error, KeyFileError::CannotOpen);
  EXPECT_EQ(load_key_file("/tmp").error, KeyFileError::NotRegular);
}

// The whole file is the key: text past the 512 bytes a key and its whitespace can take is
// not ignored, so a key followed by padding and anything else is refused.
TEST(Issue30_KeyFile, TextBeyondTheLongestKeyFileIsRefused) {
  const std::string padded = kHex32 + std::string(512 - kHex32.size(), '\n');
  const std::string fits = write_key(padded, 0600);
  EXPECT_EQ(load_key_file(fits.c_str()).error, KeyFileError::None);
  const std::string longer = write_key(padded + "00", 0600);
  EXPECT_EQ(load_key_file(longer.c_str()).error, KeyFileError::BadLength);
  for (const std::string& p : {fits, longer}) ::unlink(p.c_str());
}

}  // namespace
}  // namespace safestate::saf::test
