---- MODULE PcalCIfElse ----
(***************************************************************************)
(* A PlusCal algorithm in C syntax whose `if (...) stmt; else stmt;` has   *)
(* no braces: the PlusCal translator accepts it, tree-sitter-tlaplus's     *)
(* PlusCal grammar does not.  The algorithm is a comment: SANY, TLC and    *)
(* `safestate check` read only its translation below (issue 27, item 0).   *)
(* Expected: success, 4 distinct states, 5 generated, depth 4.            *)
(***************************************************************************)
EXTENDS Naturals

(* --algorithm PcalCIfElse {
  variable x = 0;
  {
    l: while (TRUE) {
         if (x < 3) x := x + 1; else x := 0;
       }
  }
} *)
\* BEGIN TRANSLATION (chksum(pcal) = "a1b2c3d4" /\ chksum(tla) = "e5f6a7b8")
VARIABLE x

vars == << x >>

Init == (* Global variables *)
        /\ x = 0

Next == IF x < 3 THEN x' = x + 1 ELSE x' = 0

Spec == Init /\ [][Next]_vars

\* END TRANSLATION

Inv == x \in 0..3
====
