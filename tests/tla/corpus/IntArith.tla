------------------------------ MODULE IntArith ------------------------------
(***************************************************************************)
(* A point moving on the integer grid -Lim..Lim x -Lim..Lim by knight's    *)
(* moves, with invariants that are arithmetic and Boolean identities.      *)
(*                                                                         *)
(* Exercises: Integers: + - * \div % ^, unary minus and negative literals, *)
(* floor semantics of \div and % on negative numbers, x \in Int and        *)
(* x \in Nat membership tests, < =< >= >, Booleans => <=> ~ # /= and       *)
(* BOOLEAN; an Init that generates the same state twice.                   *)
(* Expected: success.                                                      *)
(***************************************************************************)
EXTENDS Integers

CONSTANT Lim

VARIABLES x, y

\* Both sign choices yield the same state: TLC counts two initial states in
\* "states generated" but only one distinct state.
Init == \E sign \in {-1, 1} : x = 0 * sign /\ y = 0

Jumps == {<<dx, dy>> \in (-2..2) \X (-2..2) : dx * dx + dy * dy = 5}

Next == \E j \in Jumps :
          /\ x + j[1] \in -Lim..Lim
          /\ y + j[2] \in -Lim..Lim
          /\ x' = x + j[1]
          /\ y' = y + j[2]

TypeOK == x \in Int /\ y \in Int /\ x \in -Lim..Lim

Arithmetic ==
    /\ (x \div 3) * 3 + (x % 3) = x
    /\ x % 3 \in 0..2
    /\ (-7) \div 2 = -4
    /\ (-7) % 2 = 1
    /\ -x + x = 0
    /\ x - -y = x + y
    /\ (x * y) - (y * x) = 0
    /\ 2 ^ 10 = 1024
    /\ (-2) ^ 3 = -8
    /\ x ^ 2 = x * x
    /\ (x >= 0) <=> (x \in Nat)
    /\ -1 \notin Nat
    /\ x =< Lim /\ y >= -Lim

Logic ==
    /\ (x > 0) => (x # 0)
    /\ (x = y) <=> ~(x /= y)
    /\ (x + y) % 2 = (x - y) % 2
    /\ \A p, q \in BOOLEAN : (p => q) <=> (~p \/ q)
    /\ (TRUE # FALSE) /\ ~(TRUE = FALSE)
=============================================================================
