--------------------------- MODULE BankTransfer ---------------------------
(* Money transfers between accounts, with pending transfers as records    *)
(* [from, to, amount].  A transfer debits first and credits later, so the *)
(* total held in accounts is not invariant; the total including pending  *)
(* transfers is.  Constructs: records, set of records, record field       *)
(* access, a RECURSIVE sum over a set.  TLC: Invariant NoOverdraft is     *)
(* violated (the bug: the guard checks the wrong account).                *)
EXTENDS Naturals, FiniteSets
CONSTANTS Account, Initial
VARIABLES balance, pending
vars == <<balance, pending>>
RECURSIVE SumSet(_)
SumSet(S) == IF S = {} THEN 0 ELSE LET x == CHOOSE y \in S : TRUE IN x.amount + SumSet(S \ {x})
Total == LET RECURSIVE Sum(_)
             Sum(A) == IF A = {} THEN 0 ELSE LET a == CHOOSE b \in A : TRUE IN balance[a] + Sum(A \ {a})
         IN Sum(Account) + SumSet(pending)
Init == balance = [a \in Account |-> Initial] /\ pending = {}
Start(f, t, n) == /\ f # t
                  /\ balance[t] >= n
                  /\ Cardinality(pending) < 2
                  /\ [from |-> f, to |-> t, amount |-> n] \notin pending
                  /\ balance' = [balance EXCEPT ![f] = @ - n]
                  /\ pending' = pending \cup {[from |-> f, to |-> t, amount |-> n]}
Finish(tr) == /\ balance' = [balance EXCEPT ![tr.to] = @ + tr.amount]
              /\ pending' = pending \ {tr}
Next == \/ \E f, t \in Account, n \in 1..2 : Start(f, t, n)
        \/ \E tr \in pending : Finish(tr)
Spec == Init /\ [][Next]_vars
Conservation == Total = Initial * Cardinality(Account)
NoOverdraft == \A a \in Account : balance[a] >= 0
=============================================================================
