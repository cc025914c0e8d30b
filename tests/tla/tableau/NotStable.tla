---- MODULE NotStable ----
(* ~<>[]P: the fair toggle leaves 0 again and again; without WF it can stutter there. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x

Prop == ~<>[](x = 0)
====
