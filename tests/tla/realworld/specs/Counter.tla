------------------------------ MODULE Counter ------------------------------
(* A bounded counter, instantiated inside LET by LetInstance (not checked *)
(* on its own).                                                           *)
EXTENDS Naturals
CONSTANT Limit
VARIABLE c
Inc == c < Limit /\ c' = c + 1
Reset == c = Limit /\ c' = 0
Ok == c \in 0..Limit
Double(k) == 2 * k + Limit
=============================================================================
