---- MODULE PcalTrailingComma ----
(***************************************************************************)
(* A PlusCal algorithm (P syntax) whose last variable declaration ends     *)
(* with a comma (`y = 0,` before `begin`): the PlusCal translator accepts  *)
(* it, tree-sitter-tlaplus's PlusCal grammar does not (it failed the whole *)
(* module, at 1:1).  The algorithm is a comment: SANY, TLC and `safestate  *)
(* check` read only its translation below (issue 27, item 0).  Comments   *)
(* nest, as in SANY's lexer: (* this one is inside the header *) and the   *)
(* header goes on.  A string outside comments may hold the characters    *)
(* that open a comment (`Comment` below): they open none.                  *)
(* Expected: success, 3 distinct states, 4 generated, depth 3.            *)
(***************************************************************************)
EXTENDS Naturals

(* --algorithm PcalTrailingComma
variables
  x = 0,
  y = 0,
begin
  a: x := 1;
  b: y := x + 1;
end algorithm; *)
\* BEGIN TRANSLATION (chksum(pcal) = "9a8b7c6d" /\ chksum(tla) = "5e4f3a2b")
VARIABLES x, y, pc

vars == << x, y, pc >>

Init == (* Global variables *)
        /\ x = 0
        /\ y = 0
        /\ pc = "a"

a == /\ pc = "a"
     /\ x' = 1
     /\ pc' = "b"
     /\ y' = y

b == /\ pc = "b"
     /\ y' = x + 1
     /\ pc' = "Done"
     /\ x' = x

(* Allow infinite stuttering to prevent deadlock on termination. *)
Terminating == pc = "Done" /\ UNCHANGED vars

Next == a \/ b
           \/ Terminating

Spec == Init /\ [][Next]_vars

Termination == <>(pc = "Done")

\* END TRANSLATION

Comment == "(* not a comment, \\* nor this"
Inv == /\ pc = "Done" => y = 2
       /\ Comment /= "(*"
====
