---- MODULE UnclosedComment ----
(* A comment that is never closed: SANY reports it at its start (line 5). *)
EXTENDS Naturals
VARIABLE x
(* this comment is not closed
Init == x = 0
Next == x' = x
====
