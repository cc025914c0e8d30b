--------------------------- MODULE InitViolation ---------------------------
(***************************************************************************)
(* A seat allocator whose initial condition is too loose: it allows the    *)
(* two seat numbers to start out equal, which the invariant forbids.  TLC  *)
(* checks invariants on each initial state as it is generated, so the      *)
(* violation is found before any step is taken and the trace is a single   *)
(* state.                                                                  *)
(*                                                                         *)
(* Exercises: several initial states from \in, an invariant violated by an *)
(* initial state, \E in Init.  Expected: safety failure of Distinct with a *)
(* 1-state trace.                                                          *)
(***************************************************************************)
EXTENDS Naturals

VARIABLES alice, bob

Seats == 1..4

Init == /\ alice \in Seats
        /\ \E s \in Seats : bob = 5 - s

Next == \/ alice < 4 /\ alice' = alice + 1 /\ UNCHANGED bob
        \/ bob > 1 /\ bob' = bob - 1 /\ UNCHANGED alice

Distinct == alice /= bob
=============================================================================
