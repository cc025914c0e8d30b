---- MODULE EventuallySequence ----
(* <>(P /\ <>Q): the wrapping counter reaches 3 and then 0 (WF). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == <>(x = 3 /\ <>(x = 0))
====
