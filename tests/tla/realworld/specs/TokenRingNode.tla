-------------------------- MODULE TokenRingNode --------------------------
(* One node's view of a token ring, instantiated by TokenRing for each    *)
(* node (parameterised INSTANCE).  Not checked on its own.                *)
EXTENDS Naturals
CONSTANTS Self, Succ
VARIABLE holder
HasToken == holder = Self
Pass == HasToken /\ holder' = Succ
=============================================================================
