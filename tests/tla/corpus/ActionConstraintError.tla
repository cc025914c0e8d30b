---- MODULE ActionConstraintError ----
\* Minimised from difftest seed 2026, spec 766 (grammar 3).  The ACTION_CONSTRAINT
\* fails to evaluate on the step 1 -> 2; TLC's error trace ends with that successor.
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4
ACon == x' = 2 => x' < "a"
====
