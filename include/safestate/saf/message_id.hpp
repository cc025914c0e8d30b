// SPDX-License-Identifier: Apache-2.0
// The nine message ids of the Safety service protocol (SAF-03, design §10).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace safestate::saf {

/// 64-bit message id: high word 0x00000001, low word the seed's code.
enum class MessageId : std::uint64_t {
  SetEstop = 0x0000'0001'0000'013CULL,
  ReportHealthSummary = 0x0000'0001'0000'013EULL,
  ConfirmControl = 0x0000'0001'0000'012DULL,
  ReportControl = 0x0000'0001'0000'012FULL,
  ReportSubsystemState = 0x0000'0001'0000'013BULL,
  QueryHealthSummary = 0x0000'0001'0000'013DULL,
  RequestControl = 0x0000'0001'0000'012AULL,
  QueryControl = 0x0000'0001'0000'012CULL,
  SetSubsystemState = 0x0000'0001'0000'0139ULL,
};

inline constexpr std::size_t kMessageIdCount = 9;

/// Per id: the payload size of the wire format (§10) and whether the service receives it.
struct MessageSpec {
  MessageId id;
  std::string_view name;
  std::uint16_t payload_size;
  bool incoming;
};

inline constexpr std::array<MessageSpec, kMessageIdCount> kMessageSpecs{{
    {MessageId::SetEstop, "SET_ESTOP", 1, true},
    {MessageId::ReportHealthSummary, "REPORT_HEALTH_SUMMARY", 1, true},
    {MessageId::ConfirmControl, "CONFIRM_CONTROL", 1, true},
    {MessageId::ReportControl, "REPORT_CONTROL", 5, true},
    {MessageId::ReportSubsystemState, "REPORT_SUBSYSTEM_STATE", 1, true},
    {MessageId::QueryHealthSummary, "QUERY_HEALTH_SUMMARY", 0, false},
    {MessageId::RequestControl, "REQUEST_CONTROL", 6, false},
    {MessageId::QueryControl, "QUERY_CONTROL", 0, false},
    {MessageId::SetSubsystemState, "SET_SUBSYSTEM_STATE", 1, false},
}};

/// The spec of a raw 64-bit id, or nothing for an unknown id.
[[nodiscard]] constexpr std::optional<MessageSpec> find_spec(std::uint64_t raw) noexcept {
  for (const MessageSpec& s : kMessageSpecs) {
    if (static_cast<std::uint64_t>(s.id) == raw) return s;
  }
  return std::nullopt;
}

[[nodiscard]] constexpr MessageSpec spec_of(MessageId id) noexcept {
  return *find_spec(static_cast<std::uint64_t>(id));
}

}  // namespace safestate::saf
