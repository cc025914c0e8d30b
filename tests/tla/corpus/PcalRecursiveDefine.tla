---- MODULE PcalRecursiveDefine ----
(***************************************************************************)
(* A fair PlusCal algorithm (P syntax) whose `define` block              *)
(* declares a RECURSIVE operator: the PlusCal translator accepts it,       *)
(* tree-sitter-tlaplus's PlusCal grammar does not.  The algorithm is a     *)
(* comment: SANY, TLC and `safestate check` read only its translation      *)
(* below (issue 27, item 0).                                              *)
(* Expected: success, 5 distinct states, 6 generated, depth 5.            *)
(***************************************************************************)
EXTENDS Naturals

(* --fair algorithm PcalRecursiveDefine
variables n = 0, total = 0;
define
  RECURSIVE Sum(_)
  Sum(k) == IF k = 0 THEN 0 ELSE k + Sum(k - 1)
  TotalOK == total = Sum(n)
end define;
begin
  step: while n < 3 do
    n := n + 1;
    total := total + n;
  end while;
end algorithm; *)
\* BEGIN TRANSLATION (chksum(pcal) = "0f1e2d3c" /\ chksum(tla) = "4b5a6978")
VARIABLES n, total, pc

(* define statement *)
RECURSIVE Sum(_)
Sum(k) == IF k = 0 THEN 0 ELSE k + Sum(k - 1)
TotalOK == total = Sum(n)


vars == << n, total, pc >>

Init == (* Global variables *)
        /\ n = 0
        /\ total = 0
        /\ pc = "step"

step == /\ pc = "step"
        /\ IF n < 3
              THEN /\ n' = n + 1
                   /\ total' = total + n'
                   /\ pc' = "step"
              ELSE /\ pc' = "Done"
                   /\ UNCHANGED << n, total >>

(* Allow infinite stuttering to prevent deadlock on termination. *)
Terminating == pc = "Done" /\ UNCHANGED vars

Next == step
           \/ Terminating

Spec == /\ Init /\ [][Next]_vars
        /\ WF_vars(Next)

Termination == <>(pc = "Done")

\* END TRANSLATION
====
