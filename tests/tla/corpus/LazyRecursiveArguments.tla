---- MODULE LazyRecursiveArguments ----
(***************************************************************************)
(* LazyOperatorArguments with a recursive operator (called, not expanded  *)
(* at its call site): Twice(k, d) reads `d` only when k > 0, so           *)
(* Twice(0, m.dest) evaluates no `m.dest` for a message without that      *)
(* field, as in TLC (issue 27, item 0).  The recursive call passes its    *)
(* parameter `d` on unevaluated, and `k - 1` evaluated (the body reads    *)
(* `k` first: the same as TLC either way).                                *)
(* Expected: success, 4 distinct states, 5 generated, depth 3.            *)
(***************************************************************************)
EXTENDS Naturals
VARIABLES messages, handled

Join == "join"

Msgs == { [method |-> "join", dest |-> 1], [method |-> "join", dest |-> 2],
          [method |-> "leave"], [method |-> "ping", src |-> 3] }

RECURSIVE Twice(_, _)
Twice(k, d) == IF k = 0 THEN 0 ELSE d + Twice(k - 1, d)

HandleJoinRequest(d, m) ==
    /\ m.method = Join
    /\ d \notin handled
    /\ handled' = handled \cup {d}
    /\ UNCHANGED messages

Init == messages = Msgs /\ handled = {}

Next == \E m \in messages : HandleJoinRequest(m.dest, m)

Inv == \A m \in messages : Twice(IF m.method = Join THEN 2 ELSE 0, m.dest) \in {0, 2, 4}
====
