// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/key_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>

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
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    r.error = KeyFileError::CannotOpen;
    r.error_number = errno;
    return r;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    r.error = KeyFileError::NotRegular;
    return r;
  }
  r.mode = static_cast<std::uint32_t>(st.st_mode & 07777U);
  if ((st.st_mode & 077U) != 0) {
    ::close(fd);
    r.error = KeyFileError::Permissions;
    return r;
  }
  // 128 hex digits and whitespace fit; one byte more tells a too-long file.
  std::array<char, 512> text{};
  std::size_t size = 0;
  while (size < text.size()) {
    const ssize_t n = ::read(fd, text.data() + size, text.size() - size);
    if (n <= 0) break;
    size += static_cast<std::size_t>(n);
  }
  ::close(fd);
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
