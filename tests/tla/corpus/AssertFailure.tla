--------------------------- MODULE AssertFailure ---------------------------
(***************************************************************************)
(* A withdrawal action that guards itself with TLC's Assert instead of an  *)
(* enabling condition: the assertion fails as soon as a withdrawal would   *)
(* overdraw the account.  TLC stops with an evaluation error (not an       *)
(* invariant violation) and prints the trace to the state in which the     *)
(* failing action was evaluated.                                           *)
(*                                                                         *)
(* Exercises: Assert with a message, its failure during next-state         *)
(* evaluation.  Expected: error (TLC's exit code for a failed Assert).     *)
(***************************************************************************)
EXTENDS Integers, TLC

VARIABLE balance

Init == balance = 3

Deposit == balance < 5 /\ balance' = balance + 2

Withdraw(amt) ==
    /\ Assert(balance >= amt, "overdraft")
    /\ balance' = balance - amt

Next == Deposit \/ \E amt \in {2, 3} : Withdraw(amt)

NonNegative == balance >= 0
=============================================================================
