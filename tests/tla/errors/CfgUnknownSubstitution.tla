---- MODULE CfgUnknownSubstitution ----
(* The cfg substitutes Foo, which the spec does not declare: TLC stops.  *)
VARIABLE x
Init == x = 0
Next == x' = x
====
