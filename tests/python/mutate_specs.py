"""Specs shared by the `safestate mutate` tests."""

# `note` is observed, outside the VIEW and kept from step to step: a stored state can
# carry another value of it than the state it stands for (graph.confirm).
VIEWED = r"""---- MODULE Viewed ----
EXTENDS Naturals
VARIABLES inp, h, note
View == <<inp, h>>
Init == inp = 0 /\ h = 0 /\ note = "a"
Next == \E i \in {0, 1} :
    /\ inp' = i
    /\ h' = IF i = 1 THEN 0 ELSE h
    /\ note' = IF i = 1 THEN "b" ELSE note
TypeOK == inp \in 0..1 /\ h \in 0..1 /\ note \in {"a", "b"}
====
"""
