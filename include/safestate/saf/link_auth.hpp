// SPDX-License-Identifier: Apache-2.0
// Authentication of the service <-> subsystem link (design §15): with a key configured,
// every message in either direction carries a trailer after its seed payload -- a u64
// sequence number and HMAC-SHA256(key, direction byte || every byte before the MAC) --
// and the length field counts the trailer. The receiver accepts only a trailer that
// verifies, of its own direction, with a sequence above the highest it accepted, and
// hands on the message in the seed's form (the codec and the core never see the trailer).
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/saf/codec.hpp"
#include "safestate/saf/estop_extension.hpp"
#include "safestate/saf/inbound_batch.hpp"

namespace safestate::saf {

/// The first byte the MAC covers: a message of one direction reflected into the other
/// (same key) does not verify.
enum class LinkDirection : std::uint8_t { ServiceToSubsystem = 0x01, SubsystemToService = 0x02 };

inline constexpr std::size_t kLinkSequenceSize = 8;
inline constexpr std::size_t kLinkTrailer = kLinkSequenceSize + kSha256Size;
// The largest seed payload on the link (Request Control, 6 bytes) with the trailer fits.
static_assert(kHeaderSize + 6 + kLinkTrailer <= kMaxDatagram);

enum class LinkVerdict : std::uint8_t {
  Ok,
  Unauthenticated,  // no trailer: not of the sealed shape (length field = size - 10, >= 40 payload bytes)
  BadMac,           // the sealed shape, but the MAC does not verify under the key and direction
  Replay,           // authentic, sequence not above the highest accepted, within the window
  Stale,            // authentic, sequence older than the window
};

/// The receiving end's freshness state for one direction.
struct LinkReceiver {
  bool have = false;  // a sequence was accepted (or restored)
  std::uint64_t highest = 0;
  std::uint64_t window = 64;  // separates Replay from Stale in the counters only
};

/// `e` (a message of the seed's form) with the trailer for `sequence`; `e` unchanged when
/// `key` is absent (the deployment without key, as the seed), size 0 when it would not fit.
[[nodiscard]] Encoded link_seal(const Encoded& e, std::uint64_t sequence, LinkDirection direction,
                                const MacKey& key) noexcept;

struct LinkOpened {
  LinkVerdict verdict = LinkVerdict::Unauthenticated;
  std::uint64_t sequence = 0;  // meaningful when the MAC verified
};

/// Verifies the sealed datagram `data` of `size` bytes. On Ok `rx` advances to its
/// sequence and `out` holds the message in the seed's form (length field and size without
/// the trailer); otherwise `rx` and `out` are unchanged. Requires a present key.
[[nodiscard]] LinkOpened link_open(const std::uint8_t* data, std::size_t size, LinkDirection direction,
                                   const MacKey& key, LinkReceiver& rx, Datagram& out) noexcept;

}  // namespace safestate::saf
