---- MODULE TheoremNames ----
(***************************************************************************)
(* Named ASSUME and THEOREM statements used as operators (issue 27 item 4: *)
(* "Unknown operator" before): TLC evaluates A1 and T1 as definitions whose *)
(* bodies are their statements.                                            *)
(* TLC: no error, 4 states generated, 3 distinct, depth 3.                  *)
(***************************************************************************)
EXTENDS Naturals
CONSTANT N
ASSUME A1 == N > 0
THEOREM T1 == N + 0 = N
VARIABLE x
Init == x = 0 /\ A1 /\ T1
Next == x' = (x + 1) % N
Inv == A1 => x < N
====
