---- MODULE IfWithoutElse ----
(* IF without ELSE: SANY stops at the closing ==== (7:1). *)
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = IF x > 2 THEN 0
====
