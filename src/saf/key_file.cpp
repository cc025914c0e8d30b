// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/key_file.hpp"

#include <array>

#include "safestate/saf/private_file.hpp"

namespace safestate::saf {
namespace {

int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool space(char c) noexcept { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

KeyFileResult load_key_file(const char* path) noexcept {
  KeyFileResult r{};
  // 128 hex digits and whitespace fit; a longer file cannot hold a key of at most 64 bytes.
  std::array<char, 512> text{};
  const PrivateFileRead read = read_private_file(path, text.data(), text.size());
  r.mode = read.mode;
  r.error_number = read.error_number;
  switch (read.status) {
    case PrivateFileStatus::Ok: break;
    case PrivateFileStatus::Missing:
    case PrivateFileStatus::CannotOpen: r.error = KeyFileError::CannotOpen; return r;
    case PrivateFileStatus::NotRegular: r.error = KeyFileError::NotRegular; return r;
    case PrivateFileStatus::Permissions: r.error = KeyFileError::Permissions; return r;
    case PrivateFileStatus::TooLong: r.error = KeyFileError::BadLength; return r;
  }
  const std::size_t size = read.size;
  std::size_t begin = 0;
  std::size_t end = size;
  while (begin < end && space(text[begin])) ++begin;
  while (end > begin && space(text[end - 1])) --end;
  const std::size_t digits = end - begin;
  for (std::size_t i = begin; i < end; ++i) {
    if (hex_value(text[i]) < 0) {
      r.error = KeyFileError::NotHex;
      return r;
    }
  }
  if (digits % 2 != 0 || digits / 2 < kMinKeyBytes || digits / 2 > r.key.bytes.size()) {
    r.error = KeyFileError::BadLength;
    return r;
  }
  for (std::size_t i = 0; i < digits / 2; ++i) {
    r.key.bytes[i] =
        static_cast<std::uint8_t>(hex_value(text[begin + 2 * i]) * 16 + hex_value(text[begin + 2 * i + 1]));
  }
  r.key.size = digits / 2;
  return r;
}

}  // namespace safestate::saf
