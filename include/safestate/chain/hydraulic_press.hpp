#pragma once
// The hydraulic press on the state chain (docs/design/hydraulic-press.md, SCH-05,
// model models/HydraulicPress.tla). The modes sit under the root, each with its own
// stroke order and parameters. Every output is set by its state's entry function and
// cleared by its exit function, so motor-off (MX_On -> MX_Off) switches every stroke
// valve off and a restart enters Ready of the selected mode: INV-PRESS by construction.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "safestate/chain/press_inputs.hpp"
#include "safestate/chain/press_observation.hpp"
#include "safestate/chain/press_output.hpp"
#include "safestate/chain/press_outputs.hpp"
#include "safestate/chain/press_step.hpp"
#include "safestate/chain/state_chain.hpp"

namespace safestate::chain {

struct PressContext {
  PressInputs in{};
  PressOutputs out{};
};

namespace press {

// The modes (design page §3): each its own stroke order after Ready and its parameters.
struct ModeSpec {
  int steps;                                    // stroke states, Ready included
  std::array<PressStep, stroke_steps> order;    // order[0] = Ready
  std::array<const char*, stroke_steps> names;  // the states' table names
  std::uint16_t pressure_bar;                   // press pressure of the Pressing stroke
  std::uint16_t speed_mm_s;                     // ram speed of the FastAdvance stroke
};
using S = PressStep;
// clang-format off
inline constexpr ModeSpec modes[3] = {
    {9, {S::ready, S::feed, S::locate, S::clamp, S::fast_advance, S::pressing, S::blow, S::eject, S::clear_scrap},
     {"M1_Ready", "M1_Feed", "M1_Locate", "M1_Clamp", "M1_FastAdvance", "M1_Pressing", "M1_Blow", "M1_Eject", "M1_ClearScrap"},
     160, 120},
    {9, {S::ready, S::feed, S::locate, S::clamp, S::fast_advance, S::pressing, S::eject, S::blow, S::clear_scrap},
     {"M2_Ready", "M2_Feed", "M2_Locate", "M2_Clamp", "M2_FastAdvance", "M2_Pressing", "M2_Eject", "M2_Blow", "M2_ClearScrap"},
     120, 80},
    {7, {S::ready, S::feed, S::locate, S::clamp, S::pressing, S::eject, S::clear_scrap, S::none, S::none},
     {"M3_Ready", "M3_Feed", "M3_Locate", "M3_Clamp", "M3_Pressing", "M3_Eject", "M3_ClearScrap", nullptr, nullptr},
     60, 0}};
inline constexpr const char* block_names[3][7] = {
    {"Mode1", "M1_Off", "M1_On", "M1_Stroke", "M1_Aux", "M1_CoolIdle", "M1_Cooling"},
    {"Mode2", "M2_Off", "M2_On", "M2_Stroke", "M2_Aux", "M2_CoolIdle", "M2_Cooling"},
    {"Mode3", "M3_Off", "M3_On", "M3_Stroke", "M3_Aux", "M3_CoolIdle", "M3_Cooling"}};
// clang-format on

// Table indices, pre-order (design page §3): the root, then per mode its block: the mode,
// motor off, motor on, stroke, the stroke states, aux, cool idle, cooling.
inline constexpr StateIndex root = 0;
[[nodiscard]] constexpr int block_size(int m) noexcept { return 7 + modes[m - 1].steps; }
[[nodiscard]] constexpr StateIndex mode_state(int m) noexcept {
  int i = 1;
  for (int k = 1; k < m; ++k) i += block_size(k);
  return static_cast<StateIndex>(i);
}
[[nodiscard]] constexpr StateIndex off_state(int m) noexcept { return static_cast<StateIndex>(mode_state(m) + 1); }
[[nodiscard]] constexpr StateIndex on_state(int m) noexcept { return static_cast<StateIndex>(mode_state(m) + 2); }
[[nodiscard]] constexpr StateIndex stroke_state(int m) noexcept { return static_cast<StateIndex>(mode_state(m) + 3); }
// Stroke state k of mode m in the mode's order (0 = Ready).
[[nodiscard]] constexpr StateIndex step_state(int m, int k) noexcept {
  return static_cast<StateIndex>(mode_state(m) + 4 + k);
}
[[nodiscard]] constexpr StateIndex aux_state(int m) noexcept {
  return static_cast<StateIndex>(mode_state(m) + 4 + modes[m - 1].steps);
}
[[nodiscard]] constexpr StateIndex cool_idle_state(int m) noexcept { return static_cast<StateIndex>(aux_state(m) + 1); }
[[nodiscard]] constexpr StateIndex cooling_state(int m) noexcept { return static_cast<StateIndex>(aux_state(m) + 2); }
inline constexpr std::size_t state_count = 1 + 7 * 3 + 9 + 9 + 7;
static_assert(state_count == static_cast<std::size_t>(mode_state(3) + block_size(3)), "the table covers the blocks");

template <Output O>
void set_on(PressContext& c, const Requests&) noexcept {
  c.out.set(O, true);
}
template <Output O>
void set_off(PressContext& c, const Requests&) noexcept {
  c.out.set(O, false);
}
// A stroke state's entry: its valve on, and the mode's parameter for the strokes that
// have one (Pressing: pressure; FastAdvance: speed). The exit clears both.
template <int M, int K>
void step_entry(PressContext& c, const Requests&) noexcept {
  constexpr PressStep s = modes[M - 1].order[K];
  c.out.set(valve_of_step(static_cast<int>(s)), true);
  if (s == PressStep::pressing) c.out.pressure_bar = modes[M - 1].pressure_bar;
  if (s == PressStep::fast_advance) c.out.speed_mm_s = modes[M - 1].speed_mm_s;
}
template <int M, int K>
void step_exit(PressContext& c, const Requests&) noexcept {
  constexpr PressStep s = modes[M - 1].order[K];
  c.out.set(valve_of_step(static_cast<int>(s)), false);
  if (s == PressStep::pressing) c.out.pressure_bar = 0;
  if (s == PressStep::fast_advance) c.out.speed_mm_s = 0;
}

// A transition requested by a run function; the result is always ok for these sibling
// pairs of the fixed table (tested), so it is not acted on.
inline void go(const Requests& r, StateIndex src, StateIndex dst) noexcept { static_cast<void>(r.request(src, dst)); }

// The mode follows the selector whatever the motor does: a change exits the whole mode
// (motor, stroke, aux) leaf first and enters the new mode at motor off.
template <int M>
void mode_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.mode >= 1 && c.in.mode <= 3 && c.in.mode != M) go(r, mode_state(M), mode_state(c.in.mode));
}
template <int M>
void motor_off_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.motor_on && !c.in.motor_off) go(r, off_state(M), on_state(M));
}
template <int M>
void motor_on_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.motor_off) go(r, on_state(M), off_state(M));
}
template <int M>
void stroke_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.ret) go(r, stroke_state(M), stroke_state(M));  // self-transition: back to Ready
}
template <int M, int K>
void step_run(PressContext& c, const Requests& r) noexcept {
  if (K == 0) {
    if (c.in.start) go(r, step_state(M, 0), step_state(M, 1));
  } else if (c.in.step_done) {
    const int next = K + 1 < modes[M - 1].steps ? K + 1 : (c.in.continuous ? 1 : 0);
    go(r, step_state(M, K), step_state(M, next));
  }
}
template <int M>
void cool_idle_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.temp_high) go(r, cool_idle_state(M), cooling_state(M));
}
template <int M>
void cooling_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.temp_ok) go(r, cooling_state(M), cool_idle_state(M));
}

template <int M, int K>
constexpr StateDef<PressContext> step_def() noexcept {
  if constexpr (K == 0) {
    return {modes[M - 1].names[K], stroke_state(M), no_state, false, nullptr, nullptr, &step_run<M, K>, nullptr};
  } else {
    return {modes[M - 1].names[K], stroke_state(M),  no_state,        false,
            &step_entry<M, K>,     &step_exit<M, K>, &step_run<M, K>, nullptr};
  }
}

template <int M, std::size_t... K>
constexpr void put_mode(std::array<StateDef<PressContext>, state_count>& t, std::index_sequence<K...>) noexcept {
  const auto& n = block_names[M - 1];
  // clang-format off
  t[mode_state(M)] = {n[0], root, off_state(M), false, nullptr, nullptr, &mode_run<M>, nullptr};
  t[off_state(M)] = {n[1], mode_state(M), no_state, false, nullptr, nullptr, &motor_off_run<M>, nullptr};
  t[on_state(M)] = {n[2], mode_state(M), no_state, true, &set_on<Output::motor>, &set_off<Output::motor>, &motor_on_run<M>, nullptr};
  t[stroke_state(M)] = {n[3], on_state(M), step_state(M, 0), false, nullptr, nullptr, &stroke_run<M>, nullptr};
  ((t[step_state(M, static_cast<int>(K))] = step_def<M, static_cast<int>(K)>()), ...);
  t[aux_state(M)] = {n[4], on_state(M), cool_idle_state(M), false, &set_on<Output::lamp>, &set_off<Output::lamp>, nullptr, nullptr};
  t[cool_idle_state(M)] = {n[5], aux_state(M), no_state, false, nullptr, nullptr, &cool_idle_run<M>, nullptr};
  t[cooling_state(M)] = {n[6], aux_state(M), no_state, false, &set_on<Output::cool_pump>, &set_off<Output::cool_pump>, &cooling_run<M>, nullptr};
  // clang-format on
}

constexpr std::array<StateDef<PressContext>, state_count> make_table() noexcept {
  std::array<StateDef<PressContext>, state_count> t{};
  t[root] = {"Press", no_state, mode_state(1), false, nullptr, nullptr, nullptr, nullptr};
  put_mode<1>(t, std::make_index_sequence<modes[0].steps>{});
  put_mode<2>(t, std::make_index_sequence<modes[1].steps>{});
  put_mode<3>(t, std::make_index_sequence<modes[2].steps>{});
  return t;
}

inline constexpr std::array<StateDef<PressContext>, state_count> table = make_table();
static_assert(check_table(table).ok(), "the press table is a well-formed chain");

}  // namespace press

class HydraulicPress {
 public:
  HydraulicPress() noexcept : chain_(press::table, ctx_) { chain_.start(); }
  HydraulicPress(const HydraulicPress&) = delete;  // the chain refers to ctx_
  HydraulicPress& operator=(const HydraulicPress&) = delete;

  // One scan: latch the inputs, run the chain leaf to root, return the outputs.
  PressOutputs cycle(const PressInputs& in) noexcept {
    ctx_.in = in;
    chain_.run();
    chain_.work();
    return ctx_.out;
  }

  [[nodiscard]] PressObservation observe() const noexcept {
    PressObservation o{};
    o.motor = ctx_.out.on(Output::motor);
    o.outputs = ctx_.out;
    for (int m = 1; m <= 3; ++m) {
      if (!chain_.is_active(press::mode_state(m))) continue;
      o.mode = m;
      for (int k = 0; k < press::modes[m - 1].steps; ++k) {
        if (chain_.is_active(press::step_state(m, k))) o.step = press::modes[m - 1].order[k];
      }
    }
    return o;
  }

  [[nodiscard]] const StateChain<PressContext, press::state_count>& chain() const noexcept { return chain_; }

 private:
  PressContext ctx_{};
  StateChain<PressContext, press::state_count> chain_;
};

}  // namespace safestate::chain
