---- MODULE EnabledSubstM ----
(***************************************************************************)
(* Instanced by EnabledSubst (no .cfg): ENABLED inside an instanced module,  *)
(* whose variables the instantiating module substitutes.  TLC's ENABLED     *)
(* looks a primed variable up only as far as the ENABLED, not as far as the  *)
(* substitution made outside it, so x' and y' here are this module's own     *)
(* x and y, by name; a substitution made inside the ENABLED (J, an operator  *)
(* argument) is followed.  The value TLC gives each formula is noted.        *)
(***************************************************************************)
EXTENDS Naturals
VARIABLES x, y
F == ENABLED (x' = 0 /\ y' = 1)          \* TRUE: two variables, not z' twice
G == ENABLED (x' = 0 /\ x' = 1)          \* FALSE
H == ENABLED (x' = 0 /\ UNCHANGED y)     \* TRUE: y keeps y's (z's) value
Both == x' = 0 /\ y' = 1                 \* ENABLED I!Both: z' = 0 /\ z' = 1, FALSE
Op2(a, b) == ENABLED (a' = 0 /\ b' = 1)
B2 == Op2(x, y)                          \* FALSE: the arguments are z and z
J == INSTANCE EnabledSubstN WITH v <- y
K == ENABLED (J!A /\ x' = 6)             \* TRUE: J!A assigns y (v <- y), not z
Op3(a) == ENABLED (x' = 0 /\ a' = 1)     \* I!Op3(x): FALSE, both are the name x
====
