------------------------------ MODULE BagsDemo ------------------------------
(***************************************************************************)
(* A fruit basket modelled as a bag (multiset): put in a fruit while there *)
(* are fewer than Max copies of it, or take one out.                       *)
(*                                                                         *)
(* Exercises the Bags module: EmptyBag, SetToBag, BagToSet, (+), (-),      *)
(* BagIn, CopiesIn, BagCardinality, IsABag; bags compared by equality as   *)
(* functions (a fruit with zero copies leaves the domain).                 *)
(* Expected: success; (Max + 1)^3 states.                                  *)
(***************************************************************************)
EXTENDS Naturals, Bags

CONSTANT Max

Fruits == {"apple", "pear", "plum"}

VARIABLE basket

Init == basket = EmptyBag

Put(f) ==
    /\ CopiesIn(f, basket) < Max
    /\ basket' = basket (+) SetToBag({f})

Take(f) ==
    /\ BagIn(f, basket)
    /\ basket' = basket (-) SetToBag({f})

Next == \E f \in Fruits : Put(f) \/ Take(f)

TypeOK == IsABag(basket) /\ BagToSet(basket) \subseteq Fruits

Counting ==
    /\ BagCardinality(basket) = CopiesIn("apple", basket)
                                + CopiesIn("pear", basket)
                                + CopiesIn("plum", basket)
    /\ BagCardinality(basket (+) basket) = 2 * BagCardinality(basket)
    /\ basket (-) basket = EmptyBag
    /\ BagToSet(basket) = {f \in Fruits : BagIn(f, basket)}
    /\ BagToSet(basket) = DOMAIN basket
    /\ ~BagIn("kiwi", basket)
    /\ CopiesIn("kiwi", basket) = 0
=============================================================================
