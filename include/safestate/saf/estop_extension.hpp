// SPDX-License-Identifier: Apache-2.0
// The documented extension of Set Estop (design §14): the seed's payload (u8 emergency) is
// followed by the Safety Client's component id and a sequence number, and optionally by an
// HMAC-SHA256 over every byte before it. The codec accepts the three payload sizes; the
// intake (intake.hpp) decides which forms a deployment accepts.
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/saf/codec.hpp"
#include "safestate/saf/estop_form.hpp"
#include "safestate/saf/sha256.hpp"

namespace safestate::saf {

/// Bytes covered by the MAC: the header and the sequenced payload.
inline constexpr std::size_t kEstopMacCovered = kHeaderSize + kEstopSequencedPayload;
static_assert(kEstopAuthenticatedPayload == kEstopSequencedPayload + kSha256Size);
static_assert(kHeaderSize + kEstopAuthenticatedPayload <= kMaxDatagram);

/// A key for the MAC: 16 to 64 bytes, fixed storage.
struct MacKey {
  std::array<std::uint8_t, 64> bytes{};
  std::size_t size = 0;
  [[nodiscard]] bool present() const noexcept { return size > 0; }
};

/// Encodes a Set Estop of the Sequenced form, or of the Authenticated form when `key` is
/// present.
[[nodiscard]] Encoded encode_set_estop(bool emergency, std::uint32_t client_id, std::uint64_t sequence,
                                       const MacKey& key) noexcept;

/// True when `data` (a decoded Authenticated Set Estop of `size` bytes) carries the MAC of
/// its first kEstopMacCovered bytes under `key`.
[[nodiscard]] bool estop_mac_valid(const std::uint8_t* data, std::size_t size, const MacKey& key) noexcept;

}  // namespace safestate::saf
