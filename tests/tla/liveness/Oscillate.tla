---------------------------- MODULE Oscillate ----------------------------
(* A light that blinks forever under weak fairness: it is on infinitely   *)
(* often, but <>[] on fails.  Expected: temporal property violated with a *)
(* two-state cycle.                                                       *)
VARIABLE on
Init == on = FALSE
Flip == on' = ~on
Spec == Init /\ [][Flip]_on /\ WF_on(Flip)

InfinitelyOn == []<>on
EventuallyAlwaysOn == <>[]on
=============================================================================
