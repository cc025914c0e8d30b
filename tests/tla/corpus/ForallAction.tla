----------------------------- MODULE ForallAction -----------------------------
(***************************************************************************)
(* \A in an action is a conjunction, one conjunct per element, and the    *)
(* branches inside multiply successors (TLC, Tool.getNextStates OPCODE_bf: *)
(* the first element, then the others last-first).  Found by the          *)
(* differential tester (a guard \A a \in 0..1 : \E e \in 0..2 : e < 3     *)
(* gave 1 successor per state instead of TLC's 9).                        *)
(*                                                                         *)
(* Exercises: \A over CASE arms that assign and branch, TLC's order at an *)
(* invariant violation.                                                    *)
(* Expected: safety failure of Inv, 7 generated, 6 distinct, depth 2.     *)
(***************************************************************************)
EXTENDS Naturals
VARIABLES x, y
Init == x = 0 /\ y = 0
Next == \A i \in {1, 2, 3} : CASE i = 1 -> x' \in 0..2
                              [] i = 2 -> (y' = x' \/ y' = 5)
                              [] OTHER -> (x' > 0 \/ y' = 5)
Inv == ~(x = 2 /\ y = 5)
=============================================================================
