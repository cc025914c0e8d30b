--------------------------- MODULE BagsInventory ---------------------------
(* A warehouse inventory as a bag (multiset) of items, using the whole    *)
(* standard Bags module: EmptyBag, SetToBag, BagToSet, (+), (-),          *)
(* BagIn, CopiesIn, BagCardinality, \sqsubseteq, IsABag, BagUnion,        *)
(* SubBag, BagOfAll.  TLC: Invariant Capacity is violated.                *)
EXTENDS Naturals, Bags
CONSTANTS Item, Cap
VARIABLES stock, shipped
vars == <<stock, shipped>>
Init == stock = SetToBag(Item) /\ shipped = EmptyBag
Receive(i) == /\ stock' = stock (+) SetToBag({i})
              /\ UNCHANGED shipped
Ship(i) == /\ BagIn(i, stock)
           /\ stock' = stock (-) SetToBag({i})
           /\ shipped' = shipped (+) SetToBag({i})
Next == \E i \in Item : Receive(i) \/ Ship(i)
Spec == Init /\ [][Next]_vars
TypeOK == /\ IsABag(stock) /\ IsABag(shipped)
          /\ BagToSet(stock) \subseteq Item
          /\ SetToBag(BagToSet(shipped)) \sqsubseteq BagUnion({shipped, SetToBag(Item)})
          /\ \A i \in Item : CopiesIn(i, stock) >= 0
          /\ BagOfAll(LAMBDA x : x, shipped) = shipped
          /\ SubBag(SetToBag(BagToSet(stock))) # {}
Capacity == BagCardinality(stock) + BagCardinality(shipped) <= Cap
=============================================================================
