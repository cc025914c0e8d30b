---------------------------- MODULE WdBmcDomain ----------------------------
(* f[x] in Next with x outside DOMAIN f on the second step (x = 1): TLC    *)
(* stops with an evaluation error there; the invariant itself always holds. *)
EXTENDS Naturals
VARIABLE x

f == [i \in 0..0 |-> 0]

Init == x = 0
Next == x' = x + 1 + f[x]

TypeOK == x \in Nat
Small == x <= 10
=============================================================================
