------------------------------- MODULE Priming -------------------------------
(***************************************************************************)
(* Priming any expression means the expression with every variable primed *)
(* (TLC substitutes operator arguments and definitions by name).  Each     *)
(* action below is written with one form of priming; if a form were        *)
(* evaluated wrongly, its action would be lost or wrong and the counts     *)
(* would differ from TLC's.                                                *)
(*                                                                         *)
(* Exercises: a primed operator parameter bound to a variable (assigned,   *)
(* \in-assigned, UNCHANGED), bound to an expression over variables and to  *)
(* a tuple of variables (tested once they are bound), a parameter passed   *)
(* on to another operator, a primed LET definition, a LET operator with an *)
(* action body, an instance's operator I!Op' and I!Op(1)', <<x, y>>',      *)
(* (x + y)', a primed operator application Op(x)', a definition P == a'    *)
(* used as the left side of P = e (TLC assigns a'), UNCHANGED of a tuple  *)
(* parameter, of a LET name and of an operator application.               *)
(* Expected: success, 64 distinct states, 569 generated, depth 6.        *)
(***************************************************************************)
EXTENDS Naturals, Sequences
VARIABLES a, b, q
vars == <<a, b, q>>
I == INSTANCE PrimingDefs WITH v <- a

Init == a = 0 /\ b = 0 /\ q = <<1, 2>>

Dec(x) == x' = x - 1
Drop(s) == /\ s # <<>>
           /\ \E i \in 1..Len(s) : s' = [j \in 1..(Len(s)-1) |-> IF j < i THEN s[j] ELSE s[j+1]]
Pass(s) == Drop(s)
Pick(x) == x' \in {0, 1}
Grew(e) == e' > e
Same(t) == t' = t
Keep(x) == UNCHANGED x
Pair(x, y) == <<x, y>>
Double(n) == 2 * n
AP == a'

\* a parameter bound to a variable, assigned and passed on
DropQ == Pass(q) /\ UNCHANGED <<a, b>>
\* x' = x - 1 with x bound to a, guarded
DecA == a > 0 /\ Dec(a) /\ Keep(<<b, q>>)
\* x' \in S with x bound to b
PickB == Pick(b) /\ UNCHANGED <<a, q>>
\* a parameter bound to an expression over variables, tested after assignment
IncBoth == a' = a + 1 /\ b' = b /\ Grew(a + b) /\ UNCHANGED q /\ a < 3
\* a LET definition primed
LetStep == LET sum == a + b IN /\ b' = b + 1 /\ a' = a /\ sum' <= 4 /\ UNCHANGED q
\* a LET operator whose body is an action
LetAct == LET Set(x, val) == x' = val IN Set(a, 2) /\ Set(b, a) /\ UNCHANGED q
\* I!Twice' and I!Bump(1)' (an instance's operators, substitution v <- a)
InstStep == a' = (a + 1) % 4 /\ I!Twice' <= 6 /\ I!Bump(1)' > 1 /\ UNCHANGED <<b, q>>
\* <<a, b>>' and (a + b)' as tests once a' and b' are bound
Swap == a' = b /\ b' = a /\ <<a, b>>' # <<a, b>> /\ (a + b)' = a + b /\ UNCHANGED q
\* Op(x)' and a tuple parameter
Dbl == a' = 1 /\ b' = b /\ q' = q /\ Double(a)' = 2 /\ Same(Pair(b, q)) /\ a # 1
\* P = e with P == a' assigns a'
ViaDef == AP = 3 /\ UNCHANGED <<b, q>> /\ a = 0
\* UNCHANGED of an operator application
KeepApp == a' = 0 /\ b' = b /\ q' = q /\ UNCHANGED Pair(b, q) /\ a = 3

Next == DropQ \/ DecA \/ PickB \/ IncBoth \/ LetStep \/ LetAct \/ InstStep
        \/ Swap \/ Dbl \/ ViaDef \/ KeepApp

TypeOK == a \in 0..4 /\ b \in 0..4 /\ q \in Seq({1, 2})
Bounded == b <= 3
=============================================================================
