--------------------------- MODULE VendingMachine ---------------------------
(***************************************************************************)
(* A vending machine with a small stock.  Customers insert coins of value  *)
(* 1 or 2; once the credit reaches Price the machine dispenses one item    *)
(* and keeps the change as credit for the next customer.  Nobody ever      *)
(* refills it: once the stock is gone and the credit is at the price, no   *)
(* action is enabled, which TLC reports as a deadlock.                     *)
(*                                                                         *)
(* Exercises: \E-bound nondeterminism in a primed assignment, CASE with    *)
(* OTHER, bullet lists, a subtraction that can go negative, deadlock.      *)
(* Expected: deadlock failure.                                             *)
(***************************************************************************)
EXTENDS Integers

CONSTANTS Price, Stock

VARIABLES stock, credit, sold

Init == stock = Stock /\ credit = 0 /\ sold = 0

InsertCoin ==
    /\ credit < Price
    /\ \E coin \in {1, 2} : credit' = credit + coin
    /\ UNCHANGED <<stock, sold>>

Dispense ==
    /\ credit - Price >= 0
    /\ stock > 0
    /\ stock' = stock - 1
    /\ sold' = sold + 1
    /\ credit' = credit - Price

\* A state label for the invariant below.
Mode == CASE stock = 0 /\ credit >= Price -> "stuck"
          [] credit >= Price               -> "ready"
          [] OTHER                         -> "collecting"

Next == \/ InsertCoin
        \/ Dispense

TypeOK == /\ stock \in 0..Stock
          /\ credit \in 0..(Price + 1)
          /\ sold + stock = Stock
          /\ Mode \in {"stuck", "ready", "collecting"}
=============================================================================
