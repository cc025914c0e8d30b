---- MODULE StepNested ----
(* An action under a tableau formula: TLC refuses it (forms <>[]A or []<>A only). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == [](x = 0 => <>[][x' = x]_x)
====
