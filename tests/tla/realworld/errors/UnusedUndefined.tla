--------------------------- MODULE UnusedUndefined ---------------------------
(* Helper is never used by Init or Next, but refers to `Limt`, declared    *)
(* nowhere.  SANY resolves every definition, so TLC rejects the module.   *)
(* Expected: semantic error at line 10, column 19 (exit 150).             *)
EXTENDS Naturals
CONSTANT Limit
VARIABLE x
Init == x = 0
Next == x < Limit /\ x' = x + 1
Helper == x + 1 < Limt
=============================================================================
