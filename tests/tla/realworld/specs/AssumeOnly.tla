----------------------------- MODULE AssumeOnly -----------------------------
(* A module with ASSUMEs and no behaviour: its .cfg names no INIT/NEXT, so *)
(* TLC evaluates the assumptions (0 states) and succeeds.  Constructs:   *)
(* ASSUME over constants, named ASSUME, PrintT, recursive functions.     *)
(* TLC: success, 0 states.                                                *)
EXTENDS Naturals, Sequences, TLC
CONSTANT Limit
RECURSIVE Pow2(_)
Pow2(n) == IF n = 0 THEN 1 ELSE 2 * Pow2(n - 1)
gcd[m \in 1..Limit, n \in 1..Limit] == IF m = n THEN m ELSE IF m > n THEN gcd[m - n, n] ELSE gcd[m, n - m]
ASSUME Pow2(10) = 1024
ASSUME GcdOk == \A m, n \in 1..Limit : gcd[m, n] = gcd[n, m]
ASSUME Len(<<1, 2, 3>>) = 3 /\ PrintT(<<"gcd(12, 18) =", gcd[12, 18]>>)
=============================================================================
