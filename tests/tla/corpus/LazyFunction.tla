---- MODULE LazyFunction ----
(***************************************************************************)
(* Functions over infinite domains, applied at points (issue 27 item 4:    *)
(* "cannot enumerate the infinite set Int" before).  TLC keeps them lazy    *)
(* (FcnLambdaValue): application checks domain membership and evaluates     *)
(* the body, DOMAIN is the infinite set; only storing one in a state fails  *)
(* (errors/StateHoldsLazyFunction).                                         *)
(* TLC: no error, 2 states generated, 1 distinct, depth 1.                  *)
(***************************************************************************)
EXTENDS Integers
VARIABLE x
F == [i \in Int |-> i + 2]
G == [i, j \in Int |-> i + j]
H == [n \in Nat |-> [m \in Nat |-> n * m]]
Init == x = F[3] + G[3, 4] + H[2][5]
Next == x' = IF x < 20 THEN F[x] ELSE x
Inv == /\ DOMAIN F = Int
       /\ 3 \in DOMAIN F
       /\ -1 \notin DOMAIN H
       /\ F[-5] = -3
       /\ x = 22
====
