---------------------------- MODULE TlcExtTrace ----------------------------
(* TLCExt!Trace is the behaviour TLC is checking, read from its own search *)
(* state: refused as unsupported at its position, never guessed.           *)
EXTENDS Naturals, Sequences, TLCExt
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 4
Inv == Len(Trace) < 4
=============================================================================
