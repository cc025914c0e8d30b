---- MODULE UnclosedParen ----
(* A parenthesis that is never closed: SANY stops at the closing ==== (7:1). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1
====
