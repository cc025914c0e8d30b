------------------------------- MODULE Jumps -------------------------------
(* x jumps by 1 or 2; x = 5 is first reachable after 3 steps (2+2+1).   *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == \E d \in {1, 2} : x' = x + d
TypeOK == x \in Nat
NotFive == x # 5
=============================================================================
