----------------------------- MODULE Recursion -----------------------------
(* Recursion in every form TLC accepts: RECURSIVE operators called from   *)
(* Init, a recursive function definition, a recursive function defined in *)
(* LET (over Nat, applied lazily), and a LET RECURSIVE operator whose own *)
(* LET values must survive its recursive calls.  TLC: success.            *)
EXTENDS Naturals, Sequences, FiniteSets
VARIABLES n, acc
RECURSIVE Fact(_)
Fact(k) == IF k = 0 THEN 1 ELSE k * Fact(k - 1)
fib[i \in 0..12] == IF i < 2 THEN i ELSE fib[i - 1] + fib[i - 2]
SumTo(k) == LET s[j \in Nat] == IF j = 0 THEN 0 ELSE j + s[j - 1] IN s[k]
Reverse(seq) == LET RECURSIVE Rev(_)
                    Rev(t) == IF t = <<>> THEN <<>>
                              ELSE LET h == Head(t)
                                       r == Rev(Tail(t))
                                   IN Append(r, h)
                IN Rev(seq)
Init == n = Fact(3) - 6 /\ acc = <<>>
Next == /\ n < 6
        /\ n' = n + 1
        /\ acc' = Reverse(Append(acc, fib[n + 1]))
Inv == /\ SumTo(n) = (n * (n + 1)) \div 2
       /\ Len(acc) = n
       /\ \A i \in 1..Len(acc) : acc[i] = fib[Len(acc) - i + 1] \/ acc[i] \in {fib[j] : j \in 0..12}
=============================================================================
