---------------------------- MODULE InfiniteSets ----------------------------
(* Type invariants over infinite sets, tested by membership without       *)
(* enumerating them, as TLC does: Nat, Int, STRING, Seq(Nat), [D -> Nat], *)
(* [a : Nat, b : STRING], SUBSET Nat, {x \in Nat : P}, Nat \ {0}, and a   *)
(* set-builder over Seq.  TLC: success.                                   *)
EXTENDS Integers, Sequences
VARIABLES n, f, s, r, z
D == {"p", "q"}
Even == {x \in Nat : x % 2 = 0}
Init == n = 0 /\ f = [d \in D |-> 0] /\ s = <<>> /\ r = [a |-> 0, b |-> "go"] /\ z = -1
Next == /\ n < 4
        /\ n' = n + 1
        /\ f' = [f EXCEPT !["p"] = @ + 2]
        /\ s' = Append(s, n)
        /\ r' = [r EXCEPT !.a = n, !.b = IF n % 2 = 0 THEN "even" ELSE "odd"]
        /\ z' = z - n
TypeOK == /\ n \in Nat
          /\ z \in Int /\ z \notin Nat
          /\ f \in [D -> Nat]
          /\ f["p"] \in Even
          /\ s \in Seq(Nat)
          /\ s \in Seq(Int \ {-1})
          /\ {n} \in SUBSET Nat
          /\ r \in [a : Nat, b : STRING]
          /\ r.b \in STRING
          /\ n + 1 \in Nat \ {0}
          /\ s \in {t \in Seq(Nat) : Len(t) <= 4}
          /\ [d \in D |-> f[d] + 1] \in [D -> Nat \ {0}]
=============================================================================
