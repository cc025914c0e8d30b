// SPDX-License-Identifier: Apache-2.0
// The manager's state: one alternative per leaf state, holding exactly the data §4 says is
// meaningful there. Data that §4 calls "otherwise NONE/0/FALSE" is simply absent, so it
// cannot hold a stale value; entering a state constructs its data afresh.
#pragma once

#include <cstdint>
#include <type_traits>
#include <variant>

#include "safestate/fault_code.hpp"
#include "safestate/jog_setpoint.hpp"
#include "safestate/operating_mode.hpp"
#include "safestate/resume_target.hpp"
#include "safestate/state_id.hpp"
#include "safestate/stop_category.hpp"

namespace safestate {

namespace states {

struct Boot {};
struct ErrorLockout {
  FaultCode fault_code{FaultCode::None};
};
struct EstopActive {};
struct EstopResetNeeded {};
struct Idle {
  bool t2_confirmed{false};
  std::uint32_t state_cycles{0};  // cycles since the T2 confirmation (C22), 0 when not confirmed
};
struct Arming {
  OperatingMode session_mode{OperatingMode::None};
  std::uint32_t state_cycles{0};
};
struct AutoIdle {};     // session_mode is AUTO by construction (C15)
struct AutoRunning {};  // session_mode is AUTO by construction (C15, K18, K24)
struct ManualIdle {
  OperatingMode session_mode{OperatingMode::None};  // T1 or T2
};
struct ManualJogging {
  OperatingMode session_mode{OperatingMode::None};  // T1 or T2
  JogSetpoint jog{};
};
struct Stopping {
  OperatingMode session_mode{OperatingMode::None};
  StopCategory category{StopCategory::Cat1};  // CAT1 or CAT2
  std::uint32_t state_cycles{0};
  ResumeTarget resume_to{ResumeTarget::None};  // CAT2: Pause / link loss; NONE for a JOG_STOP (C28)
  JogSetpoint jog{};                           // kept only when resume_to = MANUAL_JOGGING
};
struct Hold {
  OperatingMode session_mode{OperatingMode::None};
  ResumeTarget resume_to{ResumeTarget::None};
  JogSetpoint jog{};
};

}  // namespace states

/// Alternative order = StateId order (checked below), so index() is the StateId.
using MachineState = std::variant<states::Boot, states::ErrorLockout, states::EstopActive, states::EstopResetNeeded,
                                  states::Idle, states::Arming, states::AutoIdle, states::AutoRunning,
                                  states::ManualIdle, states::ManualJogging, states::Stopping, states::Hold>;

static_assert(std::variant_size_v<MachineState> == kStateCount, "one alternative per leaf state");
static_assert(
    std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(StateId::Hold), MachineState>, states::Hold>,
    "variant alternatives must follow the StateId order");
static_assert(std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(StateId::Stopping), MachineState>,
                             states::Stopping>,
              "variant alternatives must follow the StateId order");
static_assert(
    std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(StateId::Boot), MachineState>, states::Boot>,
    "variant alternatives must follow the StateId order");
static_assert(std::is_trivially_copyable_v<MachineState>, "no heap, no destructor work");

[[nodiscard]] constexpr StateId state_id(const MachineState& s) noexcept { return static_cast<StateId>(s.index()); }

/// §4 data as the status record reports it (the "otherwise" value where not meaningful).
[[nodiscard]] OperatingMode session_mode(const MachineState& s) noexcept;
[[nodiscard]] std::uint32_t state_cycles(const MachineState& s) noexcept;
[[nodiscard]] bool t2_confirmed(const MachineState& s) noexcept;
[[nodiscard]] ResumeTarget resume_to(const MachineState& s) noexcept;
[[nodiscard]] JogSetpoint jog(const MachineState& s) noexcept;
[[nodiscard]] FaultCode fault_code(const MachineState& s) noexcept;
/// CAT1/CAT2 of the stop in progress in STOPPING, else None.
[[nodiscard]] StopCategory stopping_category(const MachineState& s) noexcept;

}  // namespace safestate
