--------------------------- MODULE InitProperty ---------------------------
(* State predicates given as PROPERTY are checked on the initial states   *)
(* only (TLC warns about this).  The first two hold, StartsAtZero does    *)
(* not: "Property StartsAtZero is violated by the initial state" (x = 2). *)
EXTENDS Naturals
VARIABLE x
Init == x \in {0, 2}
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x
StartsSmall == x < 3
StartsEven == x % 2 = 0
StartsAtZero == x = 0
=============================================================================
