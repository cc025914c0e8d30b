---- MODULE LeadsToStableLatchUnfair ----
(* The same without fairness: the counter may loop for ever. *)
EXTENDS Naturals
VARIABLES x, done
vars == <<x, done>>
Init == x = 0 /\ done = FALSE
Step == ~done /\ x' = (x + 1) % 3 /\ UNCHANGED done
Finish == ~done /\ x = 2 /\ done' = TRUE /\ UNCHANGED x
Next == Step \/ Finish
Spec == Init /\ [][Next]_vars

Prop == [](x = 2 => <>[]done)
====
