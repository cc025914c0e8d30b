---------------------------- MODULE WdLazyArgument ----------------------------
(* Operator arguments are passed unevaluated, as TLC passes them (issue 27,  *)
(* item 0): Get(f[x], x) and Step(f[x], x) read their first parameter only   *)
(* where x is in f's domain, so f[x] is obliged only there (x reaches 2,     *)
(* outside it): well-defined, proved -- in an invariant and in Next.         *)
EXTENDS Naturals
VARIABLE x

f == [i \in 0..1 |-> i]

Get(v, i) == i \in DOMAIN f => v <= 1
Step(v, i) == /\ i \in DOMAIN f => v <= 1
              /\ x' = (x + 1) % 3

Init == x = 0
Next == Step(f[x], x)

TypeOK == x \in 0..2
Lazy == Get(f[x], x)
=============================================================================
