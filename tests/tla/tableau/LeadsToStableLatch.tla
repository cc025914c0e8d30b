---- MODULE LeadsToStableLatch ----
(* [](P => <>[]Q) holds with the latch: after x = 2, done stays TRUE (SF on Finish). *)
EXTENDS Naturals
VARIABLES x, done
vars == <<x, done>>
Init == x = 0 /\ done = FALSE
Step == ~done /\ x' = (x + 1) % 3 /\ UNCHANGED done
Finish == ~done /\ x = 2 /\ done' = TRUE /\ UNCHANGED x
Next == Step \/ Finish
Spec == Init /\ [][Next]_vars /\ WF_vars(Next) /\ SF_vars(Finish)

Prop == [](x = 2 => <>[]done)
====
