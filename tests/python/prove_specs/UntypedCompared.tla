-------------------------- MODULE UntypedCompared --------------------------
\* An untyped (untracked) variable compared as a whole: `=` and `#` read it as
\* surely as `.last` does, so the prover must refuse them, not take them TRUE.
EXTENDS Naturals
VARIABLES x, log
Init == x = 0 /\ log = [last |-> 0]
Next == x' = x + 1 /\ log' = [last |-> x]
GuardedNext == log = [last |-> 0] /\ x' = x + 1 /\ log' = log
CopiedNext == x' = log /\ log' = log
TypeOK == x \in Nat
\* Violated after one step (TLC: log = [last |-> 0] /\ x = 1 is not reachable
\* past the second state), so a TRUE translation would "prove" it.
Equal == log = [last |-> 0]
Differs == log # [last |-> 1]
InTuple == <<x, log>> = <<x, [last |-> 0]>>
Fine == x >= 0
=============================================================================
