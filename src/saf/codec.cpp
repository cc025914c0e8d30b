// SPDX-License-Identifier: Apache-2.0
// The wire format of design §10: u64 id, u16 payload length, payload; little-endian.
#include "safestate/saf/codec.hpp"

#include "safestate/saf/little_endian.hpp"

namespace safestate::saf {
namespace {

using le::read_u16;
using le::read_u32;
using le::read_u64;
inline void write_le(std::uint8_t* p, std::uint64_t v, std::size_t n) noexcept { le::write(p, v, n); }

DecodeResult reject(DecodeError e) noexcept {
  DecodeResult r{};
  r.error = e;
  return r;
}

/// Set Estop has the seed's size and the two of the extension (design §14); every other
/// type exactly its spec's.
bool payload_size_valid(MessageId id, std::uint16_t length) noexcept {
  if (id == MessageId::SetEstop) {
    return length == kEstopSeedPayload || length == kEstopSequencedPayload || length == kEstopAuthenticatedPayload;
  }
  return length == spec_of(id).payload_size;
}

std::uint16_t payload_size_of(const Message& m) noexcept {
  if (m.id != MessageId::SetEstop) return spec_of(m.id).payload_size;
  switch (m.estop_form) {
    case EstopForm::Seed: return kEstopSeedPayload;
    case EstopForm::Sequenced: return kEstopSequencedPayload;
    case EstopForm::Authenticated: return kEstopAuthenticatedPayload;
  }
  return kEstopSeedPayload;
}

/// The payload's fields, range-checked.
DecodeResult decode_payload(MessageId id, const std::uint8_t* p, std::uint16_t length) noexcept {
  DecodeResult r{};
  r.message.id = id;
  switch (id) {
    case MessageId::SetEstop:
      if (p[0] > 1) return reject(DecodeError::FieldRange);
      r.message.emergency = p[0] == 1;
      if (length >= kEstopSequencedPayload) {
        r.message.estop_form = length == kEstopSequencedPayload ? EstopForm::Sequenced : EstopForm::Authenticated;
        r.message.component_id = read_u32(p + 1);
        r.message.sequence = read_u64(p + 5);
      }
      break;
    case MessageId::ReportHealthSummary:
      if (p[0] > kHealthMax) return reject(DecodeError::FieldRange);
      r.message.health = static_cast<Health>(p[0]);
      break;
    case MessageId::ConfirmControl:
      if (p[0] > kControlResponseMax) return reject(DecodeError::FieldRange);
      r.message.response = static_cast<ControlResponse>(p[0]);
      break;
    case MessageId::ReportControl:
      r.message.component_id = read_u32(p);
      r.message.authority = p[4];
      break;
    case MessageId::ReportSubsystemState:
    case MessageId::SetSubsystemState:
      if (p[0] > kSubsystemStateMax) return reject(DecodeError::FieldRange);
      r.message.subsystem_state = static_cast<SubsystemState>(p[0]);
      break;
    case MessageId::RequestControl:
      if (p[0] > kControlActionMax) return reject(DecodeError::FieldRange);
      r.message.action = static_cast<ControlAction>(p[0]);
      r.message.authority = p[1];
      r.message.component_id = read_u32(p + 2);
      break;
    case MessageId::QueryHealthSummary:
    case MessageId::QueryControl: break;
  }
  return r;
}

}  // namespace

DecodeResult decode(const std::uint8_t* data, std::size_t size) noexcept {
  if (size > kMaxDatagram) return reject(DecodeError::Oversized);
  if (data == nullptr || size < kHeaderSize) return reject(DecodeError::Truncated);
  const std::uint16_t length = read_u16(data + 8);
  if (size < kHeaderSize + length) return reject(DecodeError::Truncated);
  if (size > kHeaderSize + length) return reject(DecodeError::TrailingBytes);
  const auto spec = find_spec(read_u64(data));
  if (!spec) return reject(DecodeError::UnknownId);
  if (!payload_size_valid(spec->id, length)) return reject(DecodeError::BadLength);
  return decode_payload(spec->id, data + kHeaderSize, length);
}

Encoded encode(const Message& m) noexcept {
  Encoded e{};
  const std::uint16_t payload_size = payload_size_of(m);
  std::uint8_t* p = e.bytes.data();
  write_le(p, static_cast<std::uint64_t>(m.id), 8);
  write_le(p + 8, payload_size, 2);
  std::uint8_t* q = p + kHeaderSize;
  switch (m.id) {
    case MessageId::SetEstop:
      q[0] = m.emergency ? 1 : 0;
      if (m.estop_form != EstopForm::Seed) {
        write_le(q + 1, m.component_id, 4);
        write_le(q + 5, m.sequence, 8);  // an Authenticated form's MAC: estop_extension.cpp
      }
      break;
    case MessageId::ReportHealthSummary: q[0] = static_cast<std::uint8_t>(m.health); break;
    case MessageId::ConfirmControl: q[0] = static_cast<std::uint8_t>(m.response); break;
    case MessageId::ReportControl:
      write_le(q, m.component_id, 4);
      q[4] = m.authority;
      break;
    case MessageId::ReportSubsystemState:
    case MessageId::SetSubsystemState: q[0] = static_cast<std::uint8_t>(m.subsystem_state); break;
    case MessageId::RequestControl:
      q[0] = static_cast<std::uint8_t>(m.action);
      q[1] = m.authority;
      write_le(q + 2, m.component_id, 4);
      break;
    case MessageId::QueryHealthSummary:
    case MessageId::QueryControl: break;
  }
  e.size = kHeaderSize + payload_size;
  return e;
}

}  // namespace safestate::saf
