---- MODULE LazyOperatorArguments ----
(***************************************************************************)
(* Operator arguments are passed unevaluated, as TLC passes them (a lazy   *)
(* value, evaluated where the body first uses it): `m.dest` is never      *)
(* evaluated for the messages that have no `dest` field, because every    *)
(* body below reads the parameter only behind a guard on `m.method`       *)
(* (issue 27, item 0: TLC finds no error, safestate stopped at "Attempted *)
(* to access nonexistent field 'dest'").  The calls go through each way   *)
(* an operator is applied: an action expanded at its call site            *)
(* (HandleJoinRequest), a small state-level operator (Targeted), a LET    *)
(* operator calling it (Ok), an operator whose result is memoised         *)
(* (DestIn) and an argument passed on to another operator (Relay).        *)
(* LazyRecursiveArguments has the same with a recursive operator.         *)
(* Expected: success, 4 distinct states, 5 generated, depth 3 (deadlock   *)
(* not checked: with {1, 2} handled no message can be handled).           *)
(***************************************************************************)
EXTENDS Naturals
VARIABLES messages, handled

Join == "join"

Msgs == { [method |-> "join", dest |-> 1], [method |-> "join", dest |-> 2],
          [method |-> "leave"], [method |-> "ping", src |-> 3] }

HandleJoinRequest(d, m) ==
    /\ m.method = Join
    /\ d \notin handled
    /\ handled' = handled \cup {d}
    /\ UNCHANGED messages

Targeted(d, m) == m.method = Join => d \in 1..2

DestIn(d, m, S) == m.method = Join => \E x \in S : x = d

Relay(d, m) == Targeted(d, m)

Init == messages = Msgs /\ handled = {}

Next == \E m \in messages : HandleJoinRequest(m.dest, m)

Inv == /\ \A m \in messages : Targeted(m.dest, m)
       /\ \A m \in messages : LET Ok(d) == Targeted(d, m) IN Ok(m.dest)
       /\ \A m \in Msgs : DestIn(m.dest, m, 1..2)
       /\ \A m \in messages : Relay(m.dest, m)
====
