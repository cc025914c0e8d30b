#pragma once
// The hydraulic press on the state chain (docs/design/hydraulic-press.md, SCH-05,
// model models/HydraulicPress.tla). Every output is set by its state's entry function and
// cleared by its exit function, so motor-off (MotorOn -> MotorOff) switches every stroke
// valve off and a restart enters Ready: INV-PRESS by construction.
#include <array>
#include <cstddef>
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

// Table indices, pre-order (design page §3).
inline constexpr StateIndex root = 0, motor_off = 1, motor_on = 2, stroke = 3, aux = 34, cool_idle = 35, cooling = 36;
inline constexpr std::size_t state_count = 37;
[[nodiscard]] constexpr StateIndex mode_state(int m) noexcept { return static_cast<StateIndex>(4 + 10 * (m - 1)); }
[[nodiscard]] constexpr StateIndex step_state(int m, int k) noexcept {
  return static_cast<StateIndex>(mode_state(m) + 1 + k);
}

template <Output O>
void set_on(PressContext& c, const Requests&) noexcept {
  c.out.set(O, true);
}
template <Output O>
void set_off(PressContext& c, const Requests&) noexcept {
  c.out.set(O, false);
}

// A transition requested by a run function; the result is always ok for these sibling
// pairs of the fixed table (tested), so it is not acted on.
inline void go(const Requests& r, StateIndex src, StateIndex dst) noexcept { static_cast<void>(r.request(src, dst)); }

inline void motor_off_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.motor_on && !c.in.motor_off) go(r, motor_off, motor_on);
}
inline void motor_on_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.motor_off) go(r, motor_on, motor_off);
}
template <int M>
void mode_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.mode >= 1 && c.in.mode <= 3 && c.in.mode != M) {
    go(r, mode_state(M), mode_state(c.in.mode));
  } else if (c.in.ret) {
    go(r, mode_state(M), mode_state(M));  // self-transition: back to Ready
  }
}
template <int M, int K>
void step_run(PressContext& c, const Requests& r) noexcept {
  if (K == 0) {
    if (c.in.start) go(r, step_state(M, 0), step_state(M, 1));
  } else if (c.in.step_done) {
    const int next = K + 1 < stroke_steps ? K + 1 : (c.in.continuous ? 1 : 0);
    go(r, step_state(M, K), step_state(M, next));
  }
}
inline void cool_idle_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.temp_high) go(r, cool_idle, cooling);
}
inline void cooling_run(PressContext& c, const Requests& r) noexcept {
  if (c.in.temp_ok) go(r, cooling, cool_idle);
}

// clang-format off
inline constexpr const char* step_names[3][stroke_steps] = {
    {"M1_Ready", "M1_Feed", "M1_Locate", "M1_Clamp", "M1_FastAdvance", "M1_Pressing", "M1_Blow", "M1_Eject", "M1_ClearScrap"},
    {"M2_Ready", "M2_Feed", "M2_Locate", "M2_Clamp", "M2_FastAdvance", "M2_Pressing", "M2_Blow", "M2_Eject", "M2_ClearScrap"},
    {"M3_Ready", "M3_Feed", "M3_Locate", "M3_Clamp", "M3_FastAdvance", "M3_Pressing", "M3_Blow", "M3_Eject", "M3_ClearScrap"}};
// clang-format on
inline constexpr const char* mode_names[3] = {"Mode1", "Mode2", "Mode3"};

template <int M, int K>
constexpr StateDef<PressContext> step_def() noexcept {
  if constexpr (K == 0) {
    return {step_names[M - 1][K], mode_state(M), no_state, false, nullptr, nullptr, &step_run<M, K>, nullptr};
  } else {
    return {step_names[M - 1][K],       mode_state(M),   no_state, false, &set_on<valve_of_step(K)>,
            &set_off<valve_of_step(K)>, &step_run<M, K>, nullptr};
  }
}

template <int M, std::size_t... K>
constexpr void put_mode(std::array<StateDef<PressContext>, state_count>& t, std::index_sequence<K...>) noexcept {
  t[mode_state(M)] = {mode_names[M - 1], stroke, step_state(M, 0), false, nullptr, nullptr, &mode_run<M>, nullptr};
  ((t[step_state(M, static_cast<int>(K))] = step_def<M, static_cast<int>(K)>()), ...);
}

constexpr std::array<StateDef<PressContext>, state_count> make_table() noexcept {
  std::array<StateDef<PressContext>, state_count> t{};
  // clang-format off
  t[root] = {"Press", no_state, motor_off, false, nullptr, nullptr, nullptr, nullptr};
  t[motor_off] = {"MotorOff", root, no_state, false, nullptr, nullptr, &motor_off_run, nullptr};
  t[motor_on] = {"MotorOn", root, no_state, true, &set_on<Output::motor>, &set_off<Output::motor>, &motor_on_run, nullptr};
  t[stroke] = {"Stroke", motor_on, mode_state(1), false, nullptr, nullptr, nullptr, nullptr};
  put_mode<1>(t, std::make_index_sequence<stroke_steps>{});
  put_mode<2>(t, std::make_index_sequence<stroke_steps>{});
  put_mode<3>(t, std::make_index_sequence<stroke_steps>{});
  t[aux] = {"Aux", motor_on, cool_idle, false, &set_on<Output::lamp>, &set_off<Output::lamp>, nullptr, nullptr};
  t[cool_idle] = {"CoolIdle", aux, no_state, false, nullptr, nullptr, &cool_idle_run, nullptr};
  t[cooling] = {"Cooling", aux, no_state, false, &set_on<Output::cool_pump>, &set_off<Output::cool_pump>, &cooling_run, nullptr};
  // clang-format on
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
      for (int k = 0; k < stroke_steps; ++k) {
        if (chain_.is_active(press::step_state(m, k))) o.step = static_cast<PressStep>(k);
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
