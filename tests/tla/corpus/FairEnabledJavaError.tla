---- MODULE FairEnabledJavaError ----
\* Minimised from difftest seed 2026, specs 105, 435, 1636, 1655, 1699 (grammar 3).
\* SANY reads `{2} \X 0..2` as `({2} \X 0)..2`; TLC builds the product lazily and
\* fails inside `..` with a Java exception.  Next fails on the first state; TLC then
\* evaluates the fairness condition's ENABLED on it, meets the error again and exits
\* with 255 (without fairness, FairEnabledJavaErrorSafety, it exits with 75).
EXTENDS Naturals
VARIABLE x
Init == x \in {0, 1}
Next ==
    /\ \E <<a, b>> \in {2} \X 0..2 : TRUE
    /\ x' = x
Spec == Init /\ [][Next]_x /\ WF_x(Next)
Prop == <>(x = 0)
====
