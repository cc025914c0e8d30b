---- MODULE InitConstant ----
(* Init reads no variable: TLC evaluates it at start-up and then finds the *)
(* value FALSE, not an operator, under INIT (issue 27 item 3): "The        *)
(* initial predicate Init cannot be a constant." (exit 151; TLC gives no   *)
(* position, ours is Init in the .cfg), not a model with no states.        *)
VARIABLE x
Init == FALSE
Next == x' = x
====
