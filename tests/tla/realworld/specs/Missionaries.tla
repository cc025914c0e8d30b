---------------------------- MODULE Missionaries ----------------------------
(* Missionaries and cannibals: TLC finds a solution as a violation of     *)
(* NotSolved.  Constructs: functions from banks to sets, SUBSET with a    *)
(* filter, IsSafe via \A, model values with CHOOSE OtherBank.             *)
(* TLC: Invariant NotSolved is violated.                                  *)
EXTENDS Naturals, FiniteSets
CONSTANTS Missionaries, Cannibals
VARIABLES bank_of_boat, who_is_on_bank
Banks == {"E", "W"}
OtherBank(b) == CHOOSE x \in Banks \ {b} : TRUE
Init == /\ bank_of_boat = "E"
        /\ who_is_on_bank = [i \in Banks |-> IF i = "E" THEN Missionaries \cup Cannibals ELSE {}]
IsSafe(S) == \/ S \subseteq Cannibals
             \/ Cardinality(S \cap Cannibals) <= Cardinality(S \cap Missionaries)
Move(group) == LET oppositeBank == OtherBank(bank_of_boat)
               IN /\ bank_of_boat' = oppositeBank
                  /\ who_is_on_bank' =
                       [i \in Banks |-> IF i = oppositeBank THEN who_is_on_bank[i] \cup group
                                        ELSE who_is_on_bank[i] \ group]
Next == \E S \in SUBSET who_is_on_bank[bank_of_boat] :
          /\ Cardinality(S) \in 1..2
          /\ IsSafe(who_is_on_bank[bank_of_boat] \ S)
          /\ IsSafe(who_is_on_bank[OtherBank(bank_of_boat)] \cup S)
          /\ Move(S)
NotSolved == who_is_on_bank["E"] # {}
=============================================================================
