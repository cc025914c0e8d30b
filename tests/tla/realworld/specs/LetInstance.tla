---------------------------- MODULE LetInstance ----------------------------
(* INSTANCE inside LET, with substitutions that use a bound variable of  *)
(* the enclosing \E (LET C == INSTANCE Counter WITH c <- b, Limit <- lim).*)
(* TLC: success.                                                          *)
EXTENDS Naturals
VARIABLES a, b
Init == a = 0 /\ b = 0
StepA == LET C == INSTANCE Counter WITH c <- a, Limit <- 3 IN (C!Inc \/ C!Reset) /\ UNCHANGED b
StepB == \E lim \in {2, 4} :
           LET C == INSTANCE Counter WITH c <- b, Limit <- lim
           IN /\ C!Inc \/ (b >= lim /\ C!Reset)
              /\ UNCHANGED a
Next == StepA \/ StepB
Inv == LET C == INSTANCE Counter WITH c <- a, Limit <- 3 IN C!Ok /\ C!Double(1) = 5
=============================================================================
