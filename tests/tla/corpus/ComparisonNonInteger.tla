---- MODULE ComparisonNonInteger ----
\* Found while fixing difftest seed 2026 spec 766.  TLC's Java code for < checks its
\* operands: a string operand is the module's own evaluation error, and TLC exits with
\* 255 for it while computing successors (75 in Init); + - * .. take integers only and
\* fail as a Java exception instead (exit 75, see FairEnabledJavaErrorSafety).
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4 /\ (x = 1 => x < "a")
====
