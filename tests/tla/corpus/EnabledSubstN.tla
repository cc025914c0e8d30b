---- MODULE EnabledSubstN ----
(* Instanced by EnabledSubstM (no .cfg). *)
VARIABLE v
A == v' = 5
====
