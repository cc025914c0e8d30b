----------------------------- MODULE Recursive -----------------------------
EXTENDS Naturals
VARIABLE x
RECURSIVE Fact(_)
Fact(n) == IF n = 0 THEN 1 ELSE n * Fact(n - 1)
Init == x = 1
Next == x' = x
TypeOK == x \in Nat
Pos == Fact(x) > 0
=============================================================================
