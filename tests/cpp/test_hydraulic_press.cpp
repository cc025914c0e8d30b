// SCH-05 / INV-PRESS: the hydraulic press on the state chain against the flat defective
// reference (docs/design/hydraulic-press.md). The accident sequence is the counterexample
// `safestate check models/HydraulicPressFlat.tla` finds: motor on, start, motor off, motor on.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "safestate/chain/hydraulic_press.hpp"
#include "safestate/chain/press_event.hpp"
#include "safestate/chain/press_flat.hpp"

namespace sc = safestate::chain;

namespace {

sc::PressInputs motor_on() {
  sc::PressInputs i;
  i.motor_on = true;
  return i;
}
sc::PressInputs motor_off() {
  sc::PressInputs i;
  i.motor_off = true;
  return i;
}
sc::PressInputs start() {
  sc::PressInputs i;
  i.start = true;
  return i;
}
sc::PressInputs step_done() {
  sc::PressInputs i;
  i.step_done = true;
  return i;
}
sc::PressInputs ret() {
  sc::PressInputs i;
  i.ret = true;
  return i;
}

template <class Press>
sc::PressOutputs accident(Press& p) {
  p.cycle(motor_on());
  p.cycle(start());
  p.cycle(step_done());
  p.cycle(step_done());
  p.cycle(step_done());
  p.cycle(step_done());  // Pressing: press_valve on
  p.cycle(motor_off());
  return p.cycle(motor_on());
}

TEST(HydraulicPressFlat, INV_PRESS_AccidentRestartResumesMidStrokeAndEnergisesTheValve) {
  sc::PressFlat flat;
  const sc::PressOutputs out = accident(flat);
  EXPECT_TRUE(out.on(sc::Output::press_valve));
  EXPECT_EQ(flat.observe().step, sc::PressStep::pressing);
}

TEST(HydraulicPress, INV_PRESS_SameInputsRestartAtReadyWithEveryStrokeOutputOff) {
  sc::HydraulicPress press;
  const sc::PressOutputs out = accident(press);
  EXPECT_TRUE(out.on(sc::Output::motor));
  EXPECT_FALSE(out.any_stroke_output());
  EXPECT_EQ(press.observe().step, sc::PressStep::ready);
}

TEST(HydraulicPress, INV_PRESS_MotorOffSwitchesEveryOutputOffMidStroke) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  press.cycle(start());
  EXPECT_TRUE(press.observe().outputs.on(sc::Output::feed_valve));
  const sc::PressOutputs out = press.cycle(motor_off());
  EXPECT_EQ(out.bits, 0U);
  EXPECT_EQ(press.observe().step, sc::PressStep::none);
  EXPECT_EQ(press.observe().mode, 1);  // the mode stays selected
}

sc::PressInputs select(int m) {
  sc::PressInputs i;
  i.mode = static_cast<std::uint8_t>(m);
  return i;
}

TEST(HydraulicPress, SCH05_EachModeFollowsItsOwnStrokeOrderSingleStepBackToReady) {
  for (int m = 1; m <= 3; ++m) {
    sc::HydraulicPress press;
    press.cycle(select(m));
    press.cycle(motor_on());
    press.cycle(start());
    const auto& spec = sc::press::modes[m - 1];
    for (int k = 1; k < spec.steps; ++k) {
      EXPECT_EQ(press.observe().mode, m);
      EXPECT_EQ(press.observe().step, spec.order[k]) << "mode " << m << " step " << k;
      EXPECT_TRUE(press.observe().outputs.on(sc::valve_of_step(static_cast<int>(spec.order[k]))));
      press.cycle(step_done());
    }
    EXPECT_EQ(press.observe().step, sc::PressStep::ready);
    EXPECT_FALSE(press.observe().outputs.any_stroke_output());
  }
}

TEST(HydraulicPress, SCH05_ModeOrdersDifferAndKeepClampBeforeThePress) {
  EXPECT_NE(sc::press::modes[0].order, sc::press::modes[1].order);
  EXPECT_NE(sc::press::modes[0].steps, sc::press::modes[2].steps);
  for (const auto& spec : sc::press::modes) {
    int clamp = -1, fast = -1, pressing = -1;
    for (int k = 0; k < spec.steps; ++k) {
      if (spec.order[k] == sc::PressStep::clamp) clamp = k;
      if (spec.order[k] == sc::PressStep::fast_advance) fast = k;
      if (spec.order[k] == sc::PressStep::pressing) pressing = k;
    }
    EXPECT_GT(pressing, clamp);
    EXPECT_TRUE(fast == -1 || (fast > clamp && fast < pressing));
  }
}

TEST(HydraulicPress, SCH05_PressingDrivesTheActiveModesPressureAndClearsItOnExit) {
  for (int m = 1; m <= 3; ++m) {
    sc::HydraulicPress press;
    press.cycle(select(m));
    press.cycle(motor_on());
    press.cycle(start());
    while (press.observe().step != sc::PressStep::pressing) {
      const bool fast = press.observe().step == sc::PressStep::fast_advance;
      EXPECT_EQ(press.observe().outputs.speed_mm_s, fast ? sc::press::modes[m - 1].speed_mm_s : 0);
      EXPECT_EQ(press.observe().outputs.pressure_bar, 0);
      press.cycle(step_done());
    }
    EXPECT_EQ(press.observe().outputs.pressure_bar, sc::press::modes[m - 1].pressure_bar);
    const sc::PressOutputs out = press.cycle(motor_off());
    EXPECT_EQ(out.pressure_bar, 0);
    EXPECT_EQ(out.speed_mm_s, 0);
  }
}

TEST(HydraulicPress, SCH05_ContinuousRunningStartsTheNextCycleAtFeed) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  press.cycle(start());
  sc::PressInputs done = step_done();
  done.continuous = true;
  for (int k = 1; k < sc::press::modes[0].steps; ++k) press.cycle(done);
  EXPECT_EQ(press.observe().step, sc::PressStep::feed);
}

// UCA-7 (design page §7): a stroke output comes on only with the stroke's sensor edge, or
// with Start, which energises the feed valve alone; no other input advances the stroke.
TEST(HydraulicPress, UCA7_StrokeAdvancesOnlyOnItsSensorEdgeAndStartEnergisesFeedAlone) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  const sc::PressOutputs fed = press.cycle(start());
  EXPECT_TRUE(fed.on(sc::Output::feed_valve));
  for (int k = 2; k < sc::stroke_steps; ++k) EXPECT_FALSE(fed.on(sc::valve_of_step(k))) << k;
  sc::PressInputs others[4];
  others[0].temp_high = true;
  others[1].temp_ok = true;
  others[2].continuous = true;
  others[3].mode = 1;  // the mode already selected: no change
  for (const sc::PressInputs& in : others) {
    const sc::PressOutputs out = press.cycle(in);
    EXPECT_EQ(press.observe().step, sc::PressStep::feed);
    EXPECT_TRUE(out.on(sc::Output::feed_valve));
    EXPECT_FALSE(out.on(sc::Output::locate_valve));
  }
  const sc::PressOutputs located = press.cycle(step_done());
  EXPECT_FALSE(located.on(sc::Output::feed_valve));
  EXPECT_TRUE(located.on(sc::Output::locate_valve));
}

TEST(HydraulicPress, SCH05_RetReturnsToReadyBySelfTransition) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  press.cycle(start());
  press.cycle(step_done());
  press.cycle(ret());
  EXPECT_EQ(press.observe().step, sc::PressStep::ready);
  EXPECT_TRUE(press.observe().motor);
  EXPECT_FALSE(press.observe().outputs.any_stroke_output());
}

TEST(HydraulicPress, SCH05_ModeChangeMidCycleExitsTheMotorAndEveryStroke) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  press.cycle(start());
  const sc::PressOutputs out = press.cycle(select(2));
  EXPECT_EQ(out.bits, 0U);
  EXPECT_EQ(press.observe().mode, 2);
  EXPECT_EQ(press.observe().step, sc::PressStep::none);
  press.cycle(motor_on());
  EXPECT_EQ(press.observe().step, sc::PressStep::ready);
  EXPECT_FALSE(press.observe().outputs.any_stroke_output());
}

TEST(HydraulicPress, SCH05_SelectedModeIsKeptAcrossMotorOff) {
  sc::HydraulicPress press;
  press.cycle(select(3));
  press.cycle(motor_on());
  press.cycle(motor_off());
  press.cycle(select(2));
  press.cycle(motor_on());
  EXPECT_EQ(press.observe().mode, 2);
  EXPECT_EQ(press.observe().step, sc::PressStep::ready);
  press.cycle(motor_off());
  press.cycle(motor_on());
  EXPECT_EQ(press.observe().mode, 2);
}

TEST(HydraulicPress, SCH01_CallLogOfMotorOffExitsLeafFirstThenEntersMotorOff) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  press.cycle(start());
  press.cycle(motor_off());
  const auto& calls = press.chain().calls();
  std::vector<std::string> got;
  for (std::size_t i = 0; i < calls.size(); ++i) {
    got.push_back(std::string(sc::to_string(calls[i].kind)) + " " + sc::press::table[calls[i].state].name);
  }
  EXPECT_EQ(got, (std::vector<std::string>{"exit M1_CoolIdle", "exit M1_Aux", "exit M1_Feed", "exit M1_Stroke",
                                           "exit M1_On", "entry M1_Off"}));
  press.cycle(step_done());  // no state reacts: the scan calls nothing
  EXPECT_EQ(press.chain().calls().size(), 0U);
}

TEST(HydraulicPress, SCH03_CoolingIsAParallelSubChainExitedWithTheMotor) {
  sc::HydraulicPress press;
  press.cycle(motor_on());
  EXPECT_TRUE(press.observe().outputs.on(sc::Output::lamp));
  sc::PressInputs hot;
  hot.temp_high = true;
  press.cycle(hot);
  press.cycle(start());
  EXPECT_TRUE(press.observe().outputs.on(sc::Output::cool_pump));
  EXPECT_TRUE(press.observe().outputs.on(sc::Output::feed_valve));
  const sc::PressOutputs out = press.cycle(motor_off());
  EXPECT_FALSE(out.on(sc::Output::cool_pump) || out.on(sc::Output::lamp));
}

}  // namespace

// The counterexample `safestate check models/HydraulicPressFlat.tla --itf` wrote
// (models/traces/HydraulicPressFlat_INV_PRESS.itf.json), replayed event by event.
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> itf_events(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  const std::string s = text.str();
  std::vector<std::string> events;
  const std::regex event_re("\"event\": \"(\\w+)\"");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), event_re); it != std::sregex_iterator(); ++it) {
    if ((*it)[1] != "init") events.push_back((*it)[1]);
  }
  return events;
}

TEST(HydraulicPressAccidentReplay, INV_PRESS_CheckerCounterexampleEnergisesTheFlatPressNotTheChain) {
  const auto events =
      itf_events(std::string(SAFESTATE_SOURCE_DIR) + "/models/traces/HydraulicPressFlat_INV_PRESS.itf.json");
  ASSERT_EQ(events, (std::vector<std::string>{"motor_on", "start", "motor_off", "motor_on"}));
  sc::PressFlat flat;
  sc::HydraulicPress chain;
  bool flat_cont = false, chain_cont = false;
  sc::PressOutputs flat_out, chain_out;
  for (const std::string& e : events) {
    const auto flat_in = sc::press_inputs_of(e, flat_cont);
    const auto chain_in = sc::press_inputs_of(e, chain_cont);
    ASSERT_TRUE(flat_in && chain_in) << "not a press model event: " << e;
    flat_out = flat.cycle(*flat_in);
    chain_out = chain.cycle(*chain_in);
  }
  EXPECT_TRUE(flat_out.on(sc::Output::motor) && flat_out.on(sc::Output::feed_valve));
  EXPECT_TRUE(chain_out.on(sc::Output::motor));
  EXPECT_FALSE(chain_out.any_stroke_output());
  EXPECT_EQ(chain.observe().step, sc::PressStep::ready);
}

}  // namespace
