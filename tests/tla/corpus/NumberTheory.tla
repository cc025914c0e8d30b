---------------------------- MODULE NumberTheory ----------------------------
(***************************************************************************)
(* A library module (no .cfg, no variables): a few number-theoretic        *)
(* definitions used by Euclid (via EXTENDS) and by Operators (via a plain  *)
(* INSTANCE).                                                              *)
(*                                                                         *)
(* Exercises: RECURSIVE operators, a recursive function definition         *)
(* f[n \in S] == ..., CHOOSE, \div and %.                                  *)
(***************************************************************************)
EXTENDS Naturals

Divides(d, n) == \E k \in 0..n : n = d * k

\* Greatest common divisor by Euclid's remainder algorithm.
RECURSIVE Gcd(_, _)
Gcd(a, b) == IF b = 0 THEN a ELSE Gcd(b, a % b)

\* The same thing, by definition: the largest common divisor.
GcdSpec(a, b) == CHOOSE d \in 1..a : /\ Divides(d, a)
                                     /\ Divides(d, b)
                                     /\ \A e \in 1..a : (Divides(e, a) /\ Divides(e, b)) => e <= d

\* Factorials as a recursive function over a finite domain.
Fact[n \in 0..10] == IF n = 0 THEN 1 ELSE n * Fact[n - 1]

\* Number of binary digits of n (at least 1).
RECURSIVE Bits(_)
Bits(n) == IF n < 2 THEN 1 ELSE 1 + Bits(n \div 2)
=============================================================================
