---------------------------- MODULE PrimingDefs ----------------------------
(***************************************************************************)
(* Building block for Priming (no .cfg): an instance whose operators are   *)
(* primed from outside, I!Twice' and I!Bump(1)'.                           *)
(***************************************************************************)
EXTENDS Naturals
VARIABLE v
Twice == 2 * v
Bump(d) == v + d
=============================================================================
