---- MODULE StateHoldsUnionOfNat ----
EXTENDS Naturals
VARIABLE x
Init == x = UNION {Nat}
Next == UNCHANGED x
====
