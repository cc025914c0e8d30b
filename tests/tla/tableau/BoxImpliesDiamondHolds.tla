---- MODULE BoxImpliesDiamondHolds ----
(* []P => <>Q with weak fairness: the counter reaches 3. *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x /\ WF_x(Next)

Prop == [](x <= 3) => <>(x = 3)
====
