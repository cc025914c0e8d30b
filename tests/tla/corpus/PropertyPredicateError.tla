---- MODULE PropertyPredicateError ----
\* Minimised from difftest seed 2026, spec 1563 (grammar 3).  The property's state
\* predicate fails to evaluate (`{x} \X 0..2` is `({x} \X 0)..2`).  TLC evaluates it on
\* each state right after expanding that state, so it stops after the first expansion
\* (not after the whole search) and exits with 255.
EXTENDS Naturals
VARIABLE x
Init == x \in {0, 1, 2}
Next == x' = (x + 1) % 4
Spec == Init /\ [][Next]_x
Prop == []<>(x = 9 \/ \E <<a, b>> \in {x} \X 0..2 : TRUE)
====
