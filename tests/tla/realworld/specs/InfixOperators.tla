--------------------------- MODULE InfixOperators ---------------------------
(* User-defined infix operators with TLC's precedences: a ++ b, a -- b,   *)
(* a (+) b, a \prec b, a \oplus-like (.) and a ** b, mixed without       *)
(* parentheses where the precedence ranges allow it.  TLC: success.       *)
EXTENDS Naturals
VARIABLES a, b
a1 ++ b1 == (a1 + b1) % 7
a1 -- b1 == IF a1 >= b1 THEN a1 - b1 ELSE 0
a1 (+) b1 == a1 * 2 + b1
a1 \prec b1 == a1 < b1
a1 ** b1 == a1 * b1
a1 (.) b1 == <<a1, b1>>
Init == a = 1 /\ b = 2
Next == \/ a' = a ++ b /\ b' = b -- 1
        \/ a' = a -- b /\ b' = (b ++ 3) % 5
        \/ b \prec a /\ a' = 0 /\ b' = a
Inv == /\ a ** 2 + 1 = a * 2 + 1 - (a ** 2 - a ** 2)
       /\ (a (+) b) >= b
       /\ a ++ b ** 2 = (a + b * 2) % 7
       /\ (a (.) b)[1] = a
=============================================================================
