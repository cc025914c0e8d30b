----------------------------- MODULE Operators -----------------------------
(***************************************************************************)
(* A token walks on an (N+1) x (N+1) grid; from the east wall it may also  *)
(* jump back to the west wall.  The interesting part is in the             *)
(* definitions: every invariant is a small identity exercising one kind of *)
(* operator definition or expression.                                      *)
(*                                                                         *)
(* Exercises: plain INSTANCE of a library module, operators with           *)
(* parameters, higher-order operators (F(_) and F(_, _) parameters),       *)
(* LAMBDA, a RECURSIVE higher-order operator, LET with a local operator    *)
(* that takes a parameter, nested IF, CASE with OTHER, nested conjunction/ *)
(* disjunction bullet lists, \A and \E with several binders and tuple      *)
(* binders, CHOOSE, ENABLED in an action guard, tuples and tuple indexing. *)
(* Expected: success.                                                      *)
(***************************************************************************)
EXTENDS Integers, Sequences

INSTANCE NumberTheory

CONSTANT N

VARIABLES pos, steps

Dirs == {<<0, 1>>, <<1, 0>>, <<0, -1>>, <<-1, 0>>}

Add(p, d) == <<p[1] + d[1], p[2] + d[2]>>

InGrid(p) == \A i \in 1..2 : p[i] \in 0..N

Init == pos = <<0, 0>> /\ steps = 0

Move(d) ==
    LET q == Add(pos, d)
    IN  /\ InGrid(q)
        /\ pos' = q
        /\ steps' = (steps + 1) % 4

\* Only when an eastward move is impossible, i.e. at the east wall.
Jump ==
    /\ ~ ENABLED Move(<<1, 0>>)
    /\ pos' = <<0, pos[2]>>
    /\ UNCHANGED steps

Next == \/ \E d \in Dirs : Move(d)
        \/ Jump

---------------------------------------------------------------------------
\* Higher-order operators.
Twice(F(_), x) == F(F(x))
OnPair(F(_, _), p) == F(p[1], p[2])

RECURSIVE FoldSeq(_, _, _)
FoldSeq(F(_, _), acc, s) ==
    IF s = << >> THEN acc ELSE FoldSeq(F, F(acc, Head(s)), Tail(s))

Double(v) == 2 * v

HigherOrder ==
    /\ Twice(Double, pos[1]) = 4 * pos[1]
    /\ Twice(LAMBDA v : v - 1, steps) = steps - 2
    /\ OnPair(LAMBDA u, v : u - v, pos) = pos[1] - pos[2]
    /\ FoldSeq(LAMBDA acc, e : acc + e, 0, <<pos[1], pos[2], steps>>)
         = pos[1] + pos[2] + steps

\* Quantifiers with several and with tuple binders.
Quantifiers ==
    /\ \E <<i, j>> \in (0..N) \X (0..N) : <<i, j>> = pos
    /\ \A i, j \in 0..N : (<<i, j>> = pos) => (i = pos[1] /\ j = pos[2])
    /\ \A i \in 0..N, d \in Dirs : InGrid(Add(<<i, i>>, d)) \/ i \in {0, N}
    /\ ~ \E <<d1, d2>> \in Dirs \X Dirs : Add(d1, d2) = <<3, 3>>

\* A constant-level fact is an ASSUME, not an invariant.
ASSUME (CHOOSE d \in Dirs : d[1] + d[2] = 1 /\ d[2] = 0) = <<1, 0>>

\* The integer square root of pos[1], rounded up, found by CHOOSE.
Chosen ==
    LET r == CHOOSE i \in 0..N : i * i >= pos[1]
    IN  /\ r * r >= pos[1]
        /\ r = 0 \/ (r - 1) * (r - 1) < pos[1]

Classify(p) ==
    CASE p = <<0, 0>>  -> "origin"
      [] p[1] = p[2]   -> "diagonal"
      [] OTHER         -> IF p[1] > p[2] THEN "below" ELSE "above"

Shapes ==
    /\ \/ Classify(pos) = "origin"
       \/ /\ pos /= <<0, 0>>
          /\ \/ Classify(pos) = "diagonal"
             \/ Classify(pos) \in {"below", "above"}
    /\ LET Sq(v) == v * v
           r2    == Sq(pos[1]) + Sq(pos[2])
       IN  r2 <= 2 * Sq(N)

\* Definitions brought in by INSTANCE NumberTheory.
FromLibrary ==
    /\ Gcd(pos[1] + 1, pos[2] + 1) = GcdSpec(pos[1] + 1, pos[2] + 1)
    /\ Fact[steps] <= 6
=============================================================================
