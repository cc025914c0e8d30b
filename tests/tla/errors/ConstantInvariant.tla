---- MODULE ConstantInvariant ----
(* An invariant without variables is evaluated when TLC starts; if it is *)
(* not TRUE, TLC stops with a cfg error instead of reporting a violation. *)
(* Found by the differential tester (seed 1, spec 2).                    *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = x
Inv0 == <<1 % 3>> = <<>>
====
