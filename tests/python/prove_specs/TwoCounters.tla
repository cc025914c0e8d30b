---------------------------- MODULE TwoCounters ----------------------------
(* y counts with x, but the invariant y <= N only follows from x = y:    *)
(* not k-inductive for any k (N is symbolic), proved with the            *)
(* strengthening of TwoCountersProofs.tla, or by PDR without it.         *)
EXTENDS Naturals
CONSTANT N
ASSUME N \in Nat
VARIABLES x, y

Init == x = 0 /\ y = 0
Next == /\ x < N
        /\ x' = x + 1
        /\ y' = y + 1

TypeOK == x \in 0..N /\ y \in Nat
YBounded == y <= N
=============================================================================
