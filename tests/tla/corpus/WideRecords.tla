---- MODULE WideRecords ----
\* The native core's record and set paths (docs/checker-performance.md, session 8):
\* a 40-field record (a field found where it was last time, or by binary search in
\* TLC's order when the key varies), [r EXCEPT] with several updates and @, a set
\* of 40 values (membership by binary search), \cup / \cap / \ of sets of records,
\* function literals over 1..n and over other domains.
EXTENDS Naturals, Sequences, FiniteSets

Fields == {"f00", "f01", "f02", "f03", "f04", "f05", "f06", "f07", "f08", "f09", "f10", "f11", "f12", "f13", "f14", "f15", "f16", "f17", "f18", "f19", "f20", "f21", "f22", "f23", "f24", "f25", "f26", "f27", "f28", "f29", "f30", "f31", "f32", "f33", "f34", "f35", "f36", "f37", "f38", "f39"}
Big == 0..39

VARIABLES r, s, g

Zero == [f39 |-> 0, f38 |-> 0, f37 |-> 0, f36 |-> 0, f35 |-> 0, f34 |-> 0, f33 |-> 0, f32 |-> 0, f31 |-> 0, f30 |-> 0, f29 |-> 0, f28 |-> 0, f27 |-> 0, f26 |-> 0, f25 |-> 0, f24 |-> 0, f23 |-> 0, f22 |-> 0, f21 |-> 0, f20 |-> 0, f19 |-> 0, f18 |-> 0, f17 |-> 0, f16 |-> 0, f15 |-> 0, f14 |-> 0, f13 |-> 0, f12 |-> 0, f11 |-> 0, f10 |-> 0, f09 |-> 0, f08 |-> 0, f07 |-> 0, f06 |-> 0, f05 |-> 0, f04 |-> 0, f03 |-> 0, f02 |-> 0, f01 |-> 0, f00 |-> 0]

Init ==
    /\ r = Zero
    /\ s = {[a |-> 0, b |-> 0]}
    /\ g = [i \in 1..3 |-> 0]

Bump(k) ==
    /\ r[k] < 2
    /\ r' = [r EXCEPT ![k] = @ + 1, !.f00 = (@ + r[k]) % 3, !.f39 = IF k = "f39" THEN @ + 1 ELSE @]
    /\ s' = (s \cup {[a |-> r[k], b |-> r.f00]}) \ {[a |-> 2, b |-> 2]}
    /\ UNCHANGED g

Nest ==
    /\ g[1] < 2
    /\ g' = [g EXCEPT ![1] = @ + 1, ![3] = g[1] + @]
    /\ r' = [r EXCEPT !.f05 = [x \in {"p", "q"} |-> g[1]]["q"] % 2]
    /\ s' = s \cap {[a |-> x, b |-> y] : x \in 0..2, y \in 0..1}

Next ==
    \/ \E k \in {"f00", "f17", "f39", "f20"} : Bump(k)
    \/ Nest

Fine ==
    /\ DOMAIN r = Fields
    /\ \A k \in Fields : r[k] \in Big
    /\ r.f20 + r.f17 \in Big
    /\ {k \in Fields : r[k] > 0} \subseteq DOMAIN r
    /\ Cardinality(s) <= 20
    /\ g \in [1..3 -> 0..8]
====
