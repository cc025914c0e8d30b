---- MODULE IntervalNonInteger ----
\* Found while fixing the difftest's `..` errors: a set as a bound of `..` under \in
\* (`x \in {2} .. 3`) is TLC's Java error in `..` (exit 75 in successors); it was a
\* Python type error message here.
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 /\ x \in {2} .. 3
====
