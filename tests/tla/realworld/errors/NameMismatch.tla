--------------------------- MODULE MismatchedName ---------------------------
(* The file is NameMismatch.tla but the module is MismatchedName.         *)
(* Expected: TLC rejects it (exit 150).                                   *)
VARIABLE x
Init == x = 0
Next == x' = x
=============================================================================
