---- MODULE DuplicateRecordField ----
(* A record constructor with the field a twice.  SANY: "Non-unique fields  *)
(* in constructor." at line 6, exit 150 (issue 27 item 3).                 *)
VARIABLE x
Init ==
  x = [a |-> 1, a |-> 2]
Next == x' = x
====
