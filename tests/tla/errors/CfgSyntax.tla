----------------------------- MODULE CfgSyntax -----------------------------
(* The spec is fine; its cfg has a malformed CONSTANT assignment (line 1   *)
(* of the cfg: "N 3", the "=" is missing).  Expected: TLC rejects the cfg. *)
EXTENDS Naturals

CONSTANT N

VARIABLE x

Init == x = 0

Next == x < N /\ x' = x + 1
=============================================================================
