// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/link_auth.hpp"

#include "safestate/saf/little_endian.hpp"

namespace safestate::saf {
namespace {

using le::read_u16;
using le::read_u64;

void write_u16(std::uint8_t* p, std::size_t v) noexcept { le::write(p, v, 2); }

/// HMAC over the direction byte and `size` bytes of `data`, without a heap buffer: the
/// inner hash is fed the two parts in turn.
Digest link_mac(const MacKey& key, LinkDirection direction, const std::uint8_t* data, std::size_t size) noexcept {
  std::array<std::uint8_t, 1 + kMaxDatagram> input{};
  input[0] = static_cast<std::uint8_t>(direction);
  for (std::size_t i = 0; i < size && i < kMaxDatagram; ++i) input[1 + i] = data[i];
  return hmac_sha256(key.bytes.data(), key.size, input.data(), 1 + size);
}

}  // namespace

Encoded link_seal(const Encoded& e, std::uint64_t sequence, LinkDirection direction, const MacKey& key) noexcept {
  if (!key.present()) return e;
  Encoded s{};
  if (e.size < kHeaderSize || e.size + kLinkTrailer > kMaxDatagram) return s;
  for (std::size_t i = 0; i < e.size; ++i) s.bytes[i] = e.bytes[i];
  write_u16(s.bytes.data() + 8, read_u16(e.bytes.data() + 8) + kLinkTrailer);
  for (std::size_t i = 0; i < kLinkSequenceSize; ++i) {
    s.bytes[e.size + i] = static_cast<std::uint8_t>(sequence >> (8U * i));
  }
  const std::size_t covered = e.size + kLinkSequenceSize;
  const Digest d = link_mac(key, direction, s.bytes.data(), covered);
  for (std::size_t i = 0; i < d.size(); ++i) s.bytes[covered + i] = d[i];
  s.size = covered + kSha256Size;
  return s;
}

LinkOpened link_open(const std::uint8_t* data, std::size_t size, LinkDirection direction, const MacKey& key,
                     LinkReceiver& rx, Datagram& out) noexcept {
  LinkOpened r{};
  if (data == nullptr || !key.present() || size < kHeaderSize + kLinkTrailer || size > kMaxDatagram ||
      read_u16(data + 8) != size - kHeaderSize) {
    return r;  // Unauthenticated: no trailer (the seed's form, or garbage)
  }
  const std::size_t covered = size - kSha256Size;
  const Digest d = link_mac(key, direction, data, covered);
  if (!mac_equal(d.data(), data + covered, d.size())) {
    r.verdict = LinkVerdict::BadMac;
    return r;
  }
  r.sequence = read_u64(data + covered - kLinkSequenceSize);
  if (rx.have && r.sequence <= rx.highest) {
    r.verdict = rx.highest - r.sequence < rx.window ? LinkVerdict::Replay : LinkVerdict::Stale;
    return r;
  }
  rx.have = true;
  rx.highest = r.sequence;
  const std::size_t inner = size - kLinkTrailer;
  for (std::size_t i = 0; i < inner; ++i) out.bytes[i] = data[i];
  write_u16(out.bytes.data() + 8, inner - kHeaderSize);
  out.size = inner;
  r.verdict = LinkVerdict::Ok;
  return r;
}

}  // namespace safestate::saf
