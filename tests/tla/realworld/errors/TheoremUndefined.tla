-------------------------- MODULE TheoremUndefined --------------------------
(* The THEOREM names TypeInvariant, which is not defined (the invariant is *)
(* TypeOK).  Proofs are not checked, but their names are resolved.        *)
(* Expected: semantic error at line 11, column 19 (exit 150).             *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x < 3 /\ x' = x + 1
Spec == Init /\ [][Next]_x
TypeOK == x \in 0..3
THEOREM Spec => []TypeInvariant
=============================================================================
