// SPDX-License-Identifier: Apache-2.0
// SHA-256 (FIPS 180-4) and HMAC-SHA256 (RFC 2104) for the optional authentication of Set
// Estop (design §14). Self-contained so that the library needs no crypto package; checked
// against the FIPS 180-4 examples and the RFC 4231 test vectors (test_saf_sha256.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace safestate::saf {

inline constexpr std::size_t kSha256Size = 32;
using Digest = std::array<std::uint8_t, kSha256Size>;

/// Incremental SHA-256: update() any number of times, then final() once.
class Sha256 {
 public:
  Sha256() noexcept;
  void update(const std::uint8_t* data, std::size_t size) noexcept;
  [[nodiscard]] Digest final() noexcept;

 private:
  void block(const std::uint8_t* p) noexcept;
  std::array<std::uint32_t, 8> h_{};
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_ = 0;  // bytes
};

[[nodiscard]] Digest sha256(const std::uint8_t* data, std::size_t size) noexcept;

/// HMAC-SHA256 of `data` under `key` (a key longer than 64 bytes is hashed first).
[[nodiscard]] Digest hmac_sha256(const std::uint8_t* key, std::size_t key_size, const std::uint8_t* data,
                                 std::size_t size) noexcept;

/// Compares two MACs in time independent of where they differ.
[[nodiscard]] bool mac_equal(const std::uint8_t* a, const std::uint8_t* b, std::size_t size) noexcept;

}  // namespace safestate::saf
