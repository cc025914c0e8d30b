---- MODULE EquivEventually ----
(* (<>P) <=> (<>Q): TLC cannot handle <=> of temporal formulas (exit 255); *)
(* neither do we, in its words.                                            *)
EXTENDS Naturals
VARIABLES x, done
vars == <<x, done>>
Init == x = 0 /\ done = FALSE
Step == ~done /\ x' = (x + 1) % 3 /\ UNCHANGED done
Finish == ~done /\ x = 2 /\ done' = TRUE /\ UNCHANGED x
Next == Step \/ Finish
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)

Prop == (<>(x = 2)) <=> (<>done)
====
