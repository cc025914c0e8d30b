---- MODULE WdTwoPaths ----
(* One site, Val(x + 1) = arr[x + 1], met on two paths: defined on the first     *)
(* (x < 3), outside arr's domain on the second (x = 3). Its obligation holds    *)
(* under the disjunction of the two paths, so it fails, on a trace to x = 3.   *)
EXTENDS Naturals
VARIABLES x
arr == <<10, 20, 30>>
Val(i) == arr[i]
TypeOK == x \in 0..5
Init == x = 0
Next == \/ x < 3 /\ x' = IF Val(x + 1) > 0 THEN x + 1 ELSE x
        \/ x = 3 /\ x' = IF Val(x + 1) > 0 THEN 0 ELSE x
Bounded == x <= 3
====
