----------------------------- MODULE SeqStrings -----------------------------
(***************************************************************************)
(* An editor for short words over the alphabet {"a", "b"}: append a        *)
(* letter, delete the first letter, or swap the two halves of the word.    *)
(* The word is a sequence of one-letter strings.                           *)
(*                                                                         *)
(* Exercises: Seq(S) in a membership test (never enumerated), Len, Head,   *)
(* Tail, Append, \o, SubSeq, SelectSeq, << >>, sequence indexing, strings  *)
(* and string equality, string literals with escapes, a recursive          *)
(* operator over sequences, a CONSTRAINT bounding an otherwise infinite    *)
(* state space, an ACTION_CONSTRAINT.  Expected: success.                  *)
(***************************************************************************)
EXTENDS Naturals, Sequences

CONSTANT MaxLen

VARIABLE word

Letters == {"a", "b"}

Init == word = << >>

Type(l) == word' = Append(word, l)

Delete == word /= << >> /\ word' = Tail(word)

Rotate ==
    LET half == Len(word) \div 2
    IN  /\ half > 0
        /\ word' = SubSeq(word, half + 1, Len(word)) \o SubSeq(word, 1, half)

Next == \/ \E l \in Letters : Type(l)
        \/ Delete
        \/ Rotate

IsA(l) == l = "a"

RECURSIVE Count(_, _)
Count(s, l) == IF s = << >> THEN 0
               ELSE (IF Head(s) = l THEN 1 ELSE 0) + Count(Tail(s), l)

TypeOK == word \in Seq(Letters)

Identities ==
    /\ Len(SelectSeq(word, IsA)) = Count(word, "a")
    /\ Count(word, "a") + Count(word, "b") = Len(word)
    /\ SubSeq(word, 1, Len(word)) = word
    /\ SubSeq(word, 3, 2) = << >>
    /\ word \o << >> = word
    /\ Len(word \o word) = 2 * Len(word)
    /\ word /= << >> => /\ Head(word) = word[1]
                        /\ << Head(word) >> \o Tail(word) = word
    /\ "ab" /= "ba"
    /\ "quote\"d" /= "quoted"
    /\ <<"a", "b">> \in Seq(Letters)
    /\ DOMAIN word = 1..Len(word)

\* Bound the search: words of length at most MaxLen.
Short == Len(word) <= MaxLen

\* An action constraint naming an action: ignore rotations that leave the
\* word unchanged (such steps are still counted as generated).
RotationMoves == Rotate => word' /= word
=============================================================================
