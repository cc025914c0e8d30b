---- MODULE IfTemporal ----
(* IF over temporal formulas with a constant condition. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Fast == TRUE
Prop == IF Fast THEN []<>(x = 1) /\ <>(x = 1 /\ <>(x = 0)) ELSE <>[](x = 0)
====
