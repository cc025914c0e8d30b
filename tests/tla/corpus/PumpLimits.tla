----------------------------- MODULE PumpLimits -----------------------------
(* Limits of one pump: its top speed and a step.  Instantiated twice by    *)
(* ModuleOverride, whose .cfg overrides MaxSpeed here with `<- [M]`.       *)
EXTENDS Naturals
VARIABLE speed
MaxSpeed == 2
Up == speed < MaxSpeed /\ speed' = speed + 1
Down == speed > 0 /\ speed' = speed - 1
=============================================================================
