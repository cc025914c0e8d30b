---------------------------- MODULE TwoPhaseSym ----------------------------
(***************************************************************************)
(* The TwoPhase protocol again, checked under symmetry: the resource       *)
(* managers are interchangeable model values, so TLC needs to keep only    *)
(* one state per orbit of Permutations(RM).                                *)
(*                                                                         *)
(* Exercises: EXTENDS of a sibling module with variables, TLC's            *)
(* Permutations, SYMMETRY in the cfg.  Expected: success with fewer        *)
(* distinct states than TwoPhase.                                          *)
(***************************************************************************)
EXTENDS TwoPhase, TLC

Perms == Permutations(RM)
=============================================================================
