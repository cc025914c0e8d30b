// SPDX-License-Identifier: Apache-2.0
// §4 data accessors: the value a field has in each state, "otherwise" values elsewhere.
#include "safestate/machine_state.hpp"

namespace safestate {

namespace {

// Overload set for std::visit.
template <typename... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace

OperatingMode session_mode(const MachineState& s) noexcept {
  // Powered states carry the mode latched at Servo-on; AUTO_* are AUTO by construction.
  return std::visit(Overloaded{
                        [](const states::Arming& v) { return v.session_mode; },
                        [](const states::AutoIdle&) { return OperatingMode::Auto; },
                        [](const states::AutoRunning&) { return OperatingMode::Auto; },
                        [](const states::ManualIdle& v) { return v.session_mode; },
                        [](const states::ManualJogging& v) { return v.session_mode; },
                        [](const states::Stopping& v) { return v.session_mode; },
                        [](const states::Hold& v) { return v.session_mode; },
                        [](const auto&) { return OperatingMode::None; },
                    },
                    s);
}

std::uint32_t state_cycles(const MachineState& s) noexcept {
  if (const auto* a = std::get_if<states::Arming>(&s)) return a->state_cycles;
  if (const auto* st = std::get_if<states::Stopping>(&s)) return st->state_cycles;
  if (const auto* idle = std::get_if<states::Idle>(&s)) return idle->state_cycles;
  return 0;
}

bool t2_confirmed(const MachineState& s) noexcept {
  const auto* idle = std::get_if<states::Idle>(&s);
  return idle != nullptr && idle->t2_confirmed;
}

ResumeTarget resume_to(const MachineState& s) noexcept {
  if (const auto* st = std::get_if<states::Stopping>(&s)) return st->resume_to;
  if (const auto* h = std::get_if<states::Hold>(&s)) return h->resume_to;
  return ResumeTarget::None;
}

JogSetpoint jog(const MachineState& s) noexcept {
  if (const auto* j = std::get_if<states::ManualJogging>(&s)) return j->jog;
  if (const auto* st = std::get_if<states::Stopping>(&s)) return st->jog;
  if (const auto* h = std::get_if<states::Hold>(&s)) return h->jog;
  return JogSetpoint{};
}

FaultCode fault_code(const MachineState& s) noexcept {
  const auto* e = std::get_if<states::ErrorLockout>(&s);
  return e != nullptr ? e->fault_code : FaultCode::None;
}

StopCategory stopping_category(const MachineState& s) noexcept {
  const auto* st = std::get_if<states::Stopping>(&s);
  return st != nullptr ? st->category : StopCategory::None;
}

}  // namespace safestate
