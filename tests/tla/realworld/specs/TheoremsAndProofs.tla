------------------------- MODULE TheoremsAndProofs -------------------------
(* A spec with TLAPS proof material, which TLC parses and ignores:        *)
(* THEOREM with a hierarchical PROOF (<1>1., BY, DEF, OBVIOUS, QED),      *)
(* LEMMA, AXIOM, named ASSUME, USE.  Euclid's algorithm as in the         *)
(* published Euclid example.  TLC: success.                               *)
EXTENDS Naturals
CONSTANTS M, N
ASSUME Positive == M \in Nat \ {0} /\ N \in Nat \ {0}
VARIABLES x, y
Divides(p, q) == \E k \in 0..q : q = p * k
GCD(p, q) == CHOOSE g \in 1..p : /\ Divides(g, p) /\ Divides(g, q)
                                 /\ \A h \in 1..p : Divides(h, p) /\ Divides(h, q) => h <= g
Init == x = M /\ y = N
Next == \/ x > y /\ x' = x - y /\ y' = y
        \/ y > x /\ y' = y - x /\ x' = x
Spec == Init /\ [][Next]_<<x, y>>
TypeOK == x \in Nat \ {0} /\ y \in Nat \ {0}
Correct == x = y => x = GCD(M, N)
AXIOM GCDSelf == \A p \in Nat \ {0} : GCD(p, p) = p
LEMMA TypeCorrect == Spec => []TypeOK
<1>1. Init => TypeOK
  BY Positive DEF Init, TypeOK
<1>2. TypeOK /\ [Next]_<<x, y>> => TypeOK'
  <2>1. CASE x > y
    BY <2>1 DEF TypeOK, Next
  <2>2. CASE y > x
    BY <2>2 DEF TypeOK, Next
  <2>3. QED
    OBVIOUS
<1>3. QED
  BY <1>1, <1>2
THEOREM Spec => []Correct
  OBVIOUS
USE DEF TypeOK
=============================================================================
