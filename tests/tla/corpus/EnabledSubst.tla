---- MODULE EnabledSubst ----
(***************************************************************************)
(* ENABLED under INSTANCE substitution (issue 27, item 2): EnabledSubstM's   *)
(* x and y are both substituted by z, and each invariant holds in TLC only   *)
(* if ENABLED treats primed variables as TLC does (see EnabledSubstM).        *)
(* Substituting z for x and y inside F gives ENABLED (z' = 0 /\ z' = 1),     *)
(* FALSE, and a false violation in the initial state.                        *)
(* TLC: no error, 3 states generated, 2 distinct, depth 2.                   *)
(***************************************************************************)
EXTENDS Naturals
VARIABLES z, x
I == INSTANCE EnabledSubstM WITH x <- z, y <- z
Init == z = 0 /\ x = 0
Next == z' = 1 - z /\ x' = x
InvF == I!F
InvG == ~I!G
InvH == I!H
InvBoth == ~ENABLED I!Both
InvB2 == ~I!B2
InvK == I!K
InvOp3 == ~I!Op3(x)
====
