----------------------------- MODULE WdGuarded -----------------------------
(* Applications guarded as TLA+ evaluates them (left to right, stopping     *)
(* early in /\, \/, =>, IF): well-defined, proved.  Vacuous's antecedent    *)
(* holds in no state: reported vacuous.                                     *)
EXTENDS Naturals, Sequences
VARIABLE x, q

f == [i \in 0..1 |-> i]

Init == x = 0 /\ q = <<>>
Next == /\ x' = (x + 1) % 3
        /\ q' = IF Len(q) < 2 THEN Append(q, x) ELSE Tail(q)
        /\ x \in DOMAIN f => f[x] <= 1

TypeOK == x \in 0..2 /\ q \in Seq(0..2) /\ Len(q) <= 2
ImpliesGuard == x \in DOMAIN f => f[x] = x
IfGuard == IF x \in DOMAIN f THEN f[x] >= 0 ELSE x = 2
AndGuard == ~(x \in DOMAIN f /\ f[x] > 1)
OrGuard == x = 2 \/ f[x] <= 1
CaseGuard == CASE x \in DOMAIN f -> f[x] <= 1 [] OTHER -> TRUE
HeadGuard == q # <<>> => Head(q) \in 0..2
DivGuard == x > 0 => 6 \div x >= 3
Vacuous == x > 5 => f[x] = 0
=============================================================================
