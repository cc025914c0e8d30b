---- MODULE PropertyAssert ----
\* An Assert that fails in a property's state predicate: TLC evaluates the predicate on
\* each state right after expanding it and stops there with the Assert's exit code 14.
EXTENDS Naturals, TLC
VARIABLE x
Init == x \in {0, 1, 2}
Next == x' = (x + 1) % 4
Spec == Init /\ [][Next]_x
Prop == []<>(Assert(x < 2, "too big"))
====
