#pragma once
// DEFECTIVE REFERENCE — never use as a product. A faithful C++ rendering of the seed
// document's flat switch-case press program (docs/design/hydraulic-press.md §5, model
// models/HydraulicPressFlat.tla), bug included: motor-off does not reset Cur_Runing, so a
// motor restart resumes the stroke where it stopped. Kept only to reproduce the accident.
#include "safestate/chain/press_inputs.hpp"
#include "safestate/chain/press_observation.hpp"
#include "safestate/chain/press_output.hpp"
#include "safestate/chain/press_outputs.hpp"
#include "safestate/chain/press_step.hpp"

namespace safestate::chain {

class PressFlat {
 public:
  PressOutputs cycle(const PressInputs& in) noexcept {
    if (in.motor_on) MoToOut = true;    // if(MON==true)  MoToOut=1;
    if (in.motor_off) MoToOut = false;  // if(MOFF==true) MoToOut=0;
    if (MoToOut) {                      // if(MoToOut==1) ... and no else: the bug
      if (in.mode >= 1 && in.mode <= 3) FangShi = in.mode;
      switch (Cur_Runing) {  // the three modes share one sequence (design §3)
        case 0:
          if (in.ret) Cur_Runing = 0;
          else if (in.start) Cur_Runing = 1;
          break;
        case 8:
          if (in.ret) Cur_Runing = 0;
          else if (in.step_done) Cur_Runing = in.continuous ? 1 : 0;
          break;
        default:
          if (in.ret) Cur_Runing = 0;
          else if (in.step_done) Cur_Runing = Cur_Runing + 1;
          break;
      }
    }
    // Output stage: the current stroke's valve while the motor runs.
    outputs_ = PressOutputs{};
    outputs_.set(Output::motor, MoToOut);
    if (MoToOut && step_has_valve(Cur_Runing)) outputs_.set(valve_of_step(Cur_Runing), true);
    return outputs_;
  }

  [[nodiscard]] PressObservation observe() const noexcept {
    return {MoToOut, FangShi, static_cast<PressStep>(Cur_Runing), outputs_};
  }

 private:
  // The document's variable names.
  bool MoToOut = false;
  int Cur_Runing = 0;
  int FangShi = 1;
  PressOutputs outputs_{};
};

}  // namespace safestate::chain
