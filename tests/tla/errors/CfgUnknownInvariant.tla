------------------------ MODULE CfgUnknownInvariant ------------------------
(* The spec is fine; its cfg names an invariant, TypeOk, that the module   *)
(* does not define (it defines TypeOK).  Expected: TLC rejects the cfg.    *)
EXTENDS Naturals

VARIABLE x

Init == x = 0

Next == x < 3 /\ x' = x + 1

TypeOK == x \in 0..3
=============================================================================
