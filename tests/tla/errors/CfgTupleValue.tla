---- MODULE CfgTupleValue ----
(* The spec is fine; its cfg gives the constant N the tuple <<1, 2>>, which TLC *)
(* 1.8.0's cfg grammar does not have (nor negative numbers).  Expected: TLC     *)
(* rejects the cfg (ConfigFileException, exit 255).                             *)
CONSTANT N
VARIABLE x
Init == x = N
Next == x' = x
====
