-------------------------- MODULE PrefixPrecedence --------------------------
(* SANY rejects a prefix operator beside an unparenthesised infix operator  *)
(* whose precedence range overlaps the one SANY gives it: UNION S \X T      *)
(* needs parentheses, while UNION S \cup T does not.  Found by the          *)
(* differential tester (grammar 3).  Expected: precedence conflict, 150.    *)
EXTENDS Naturals

VARIABLE x

Init == x = UNION {{0}, {1}} \cup {2}

Next == \E <<a, b>> \in UNION {{0}, {1}} \X {2} : x' = {a + b}
=============================================================================
