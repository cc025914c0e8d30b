// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/sequence_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "safestate/saf/private_file.hpp"

namespace safestate::saf {
namespace {

constexpr std::size_t kMaxFile = 128;
constexpr std::size_t kMaxPath = 4000;

/// `text` is "<key> <value>" with value a u64 in decimal (no sign, no leading zero but
/// "0", at most 20 digits, no overflow), or "none" where `none_allowed`.
bool parse_value(std::string_view text, std::string_view key, bool none_allowed, bool& have,
                 std::uint64_t& value) noexcept {
  if (text.size() <= key.size() + 1 || text.substr(0, key.size()) != key || text[key.size()] != ' ') return false;
  const std::string_view v = text.substr(key.size() + 1);
  if (none_allowed && v == "none") {
    have = false;
    value = 0;
    return true;
  }
  if (v.empty() || v.size() > 20 || (v.size() > 1 && v[0] == '0')) return false;
  std::uint64_t n = 0;
  for (char c : v) {
    if (c < '0' || c > '9') return false;
    const auto digit = static_cast<std::uint64_t>(c - '0');
    if (n > (UINT64_MAX - digit) / 10U) return false;
    n = n * 10U + digit;
  }
  have = true;
  value = n;
  return true;
}

SequenceFileResult bad(std::size_t line, std::string_view expected) noexcept {
  SequenceFileResult r{};
  r.error = SequenceFileError::BadFormat;
  r.line = line;
  r.expected = expected;
  return r;
}

SequenceFileResult write_error(int error_number) noexcept {
  SequenceFileResult r{};
  r.error = SequenceFileError::CannotWrite;
  r.error_number = error_number;
  return r;
}

bool write_all(int fd, const char* data, std::size_t size) noexcept {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

SequenceFileResult load_sequence_file(const char* path) noexcept {
  SequenceFileResult r{};
  std::array<char, kMaxFile> text{};
  const PrivateFileRead read = read_private_file(path, text.data(), text.size());
  r.mode = read.mode;
  r.error_number = read.error_number;
  switch (read.status) {
    case PrivateFileStatus::Ok: break;
    case PrivateFileStatus::Missing: r.error = SequenceFileError::Missing; return r;
    case PrivateFileStatus::CannotOpen: r.error = SequenceFileError::CannotOpen; return r;
    case PrivateFileStatus::NotRegular: r.error = SequenceFileError::NotRegular; return r;
    case PrivateFileStatus::Permissions: r.error = SequenceFileError::Permissions; return r;
    case PrivateFileStatus::TooLong: r.error = SequenceFileError::TooLong; return r;
  }
  const std::size_t size = read.size;
  static constexpr std::array<std::string_view, 4> kExpected = {
      "safestate-saf-sequence 1",
      "estop <highest accepted Set Estop sequence, decimal> or estop none",
      "subsystem <highest accepted subsystem sequence, decimal> or subsystem none",
      "service <next sequence of the service's messages, decimal>",
  };
  const std::string_view all(text.data(), size);
  std::size_t begin = 0;
  SequenceState s{};
  for (std::size_t line = 0; line < kExpected.size(); ++line) {
    const std::size_t end = all.find('\n', begin);
    if (end == std::string_view::npos) return bad(line + 1, kExpected[line]);  // missing, or no newline
    const std::string_view l = all.substr(begin, end - begin);
    bool ok = false;
    bool have = false;
    switch (line) {
      case 0: ok = l == kSequenceFileMagic; break;
      case 1: ok = parse_value(l, "estop", true, s.have_estop, s.estop); break;
      case 2: ok = parse_value(l, "subsystem", true, s.have_subsystem, s.subsystem); break;
      default: ok = parse_value(l, "service", false, have, s.service); break;
    }
    if (!ok) return bad(line + 1, kExpected[line]);
    begin = end + 1;
  }
  if (begin != size) return bad(kExpected.size() + 1, "the end of the file (four lines)");
  r.state = s;
  return r;
}

SequenceFileResult store_sequence_file(const char* path, const SequenceState& state) noexcept {
  const std::size_t n = std::strlen(path);
  if (n == 0 || n > kMaxPath) return write_error(ENAMETOOLONG);
  std::array<char, kMaxPath + 8> tmp{};
  std::snprintf(tmp.data(), tmp.size(), "%s.tmp", path);
  std::array<char, kMaxPath + 2> folder{};
  const char* slash = std::strrchr(path, '/');
  if (slash == nullptr) {
    folder[0] = '.';
  } else if (slash == path) {
    folder[0] = '/';
  } else {
    std::memcpy(folder.data(), path, static_cast<std::size_t>(slash - path));
  }

  std::array<char, kMaxFile + 1> text{};
  std::array<char, 24> estop{};
  std::array<char, 24> subsystem{};
  if (state.have_estop) {
    std::snprintf(estop.data(), estop.size(), "%llu", static_cast<unsigned long long>(state.estop));
  } else {
    std::snprintf(estop.data(), estop.size(), "none");
  }
  if (state.have_subsystem) {
    std::snprintf(subsystem.data(), subsystem.size(), "%llu", static_cast<unsigned long long>(state.subsystem));
  } else {
    std::snprintf(subsystem.data(), subsystem.size(), "none");
  }
  const int size = std::snprintf(text.data(), text.size(), "%.*s\nestop %s\nsubsystem %s\nservice %llu\n",
                                 static_cast<int>(kSequenceFileMagic.size()), kSequenceFileMagic.data(), estop.data(),
                                 subsystem.data(), static_cast<unsigned long long>(state.service));

  // A leftover temporary file (a crash between create and rename) is replaced; O_NOFOLLOW
  // refuses a symbolic link planted there.
  const int fd = ::open(tmp.data(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0) return write_error(errno);
  // The mode of a replaced leftover could be wider than 0600.
  if (::fchmod(fd, 0600) != 0 || !write_all(fd, text.data(), static_cast<std::size_t>(size)) || ::fsync(fd) != 0) {
    const int e = errno;
    ::close(fd);
    ::unlink(tmp.data());
    return write_error(e);
  }
  if (::close(fd) != 0) {
    const int e = errno;
    ::unlink(tmp.data());
    return write_error(e);
  }
  if (::rename(tmp.data(), path) != 0) {
    const int e = errno;
    ::unlink(tmp.data());
    return write_error(e);
  }
  // The rename is durable only once the folder is.
  const int dir = ::open(folder.data(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return write_error(errno);
  const int synced = ::fsync(dir);
  const int e = errno;
  ::close(dir);
  if (synced != 0) return write_error(e);
  SequenceFileResult r{};
  r.state = state;
  return r;
}

}  // namespace safestate::saf
