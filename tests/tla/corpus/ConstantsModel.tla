--------------------------- MODULE ConstantsModel ---------------------------
(***************************************************************************)
(* A job scheduler: workers (model values) take numbered jobs, one at a    *)
(* time, and finish them; when every job is done the batch starts over.    *)
(* An idle worker holds the model value Idle, which TLC compares for       *)
(* (in)equality with the integers that name jobs.                          *)
(*                                                                         *)
(* Exercises every kind of CONSTANT the cfg can give: a set of model       *)
(* values, a single model value, a string, an integer, an operator         *)
(* constant replaced by a definition (Cost <- TripleCost) and an ordinary  *)
(* constant replaced by a definition (Budget <- DefaultBudget); true       *)
(* ASSUMEs, one of them named; a RECURSIVE sum over a set.                 *)
(* Expected: success.                                                      *)
(***************************************************************************)
EXTENDS Naturals, FiniteSets

CONSTANTS Workers,   \* a set of model values
          Idle,      \* a model value
          Label,     \* a string
          NumJobs,   \* an integer
          Cost(_),   \* an operator, substituted in the cfg
          Budget     \* substituted in the cfg by a definition

ASSUME Workers /= {} /\ Idle \notin Workers
ASSUME JobsExist == NumJobs \in Nat \ {0}
ASSUME Label = "batch" /\ Label \in STRING

TripleCost(j) == 3 * j
DefaultBudget == (3 * NumJobs * (NumJobs + 1)) \div 2

Jobs == 1..NumJobs

VARIABLES holds, done

Init == holds = [w \in Workers |-> Idle] /\ done = {}

Busy == {holds[w] : w \in {v \in Workers : holds[v] /= Idle}}

Take(w, j) ==
    /\ holds[w] = Idle
    /\ j \notin done \cup Busy
    /\ holds' = [holds EXCEPT ![w] = j]
    /\ UNCHANGED done

Finish(w) ==
    /\ holds[w] /= Idle
    /\ done' = done \cup {holds[w]}
    /\ holds' = [holds EXCEPT ![w] = Idle]

NewBatch == done = Jobs /\ done' = {} /\ UNCHANGED holds

Next == \/ \E w \in Workers : \/ Finish(w)
                              \/ \E j \in Jobs : Take(w, j)
        \/ NewBatch

RECURSIVE SetSum(_)
SetSum(S) == IF S = {} THEN 0
             ELSE LET x == CHOOSE x \in S : TRUE IN Cost(x) + SetSum(S \ {x})

TypeOK == /\ holds \in [Workers -> Jobs \cup {Idle}]
          /\ done \subseteq Jobs

WithinBudget == SetSum(done \cup Busy) <= Budget

NoSharing == \A v, w \in Workers : v /= w /\ holds[v] /= Idle => holds[v] /= holds[w]
=============================================================================
