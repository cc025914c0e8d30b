----------------------------- MODULE WdChoose -----------------------------
(* The next value is CHOOSEn above x in 0..3: at x = 3 there is none.      *)
EXTENDS Naturals
VARIABLE x

Init == x = 0
Next == x' = CHOOSE i \in 0..3 : i > x

TypeOK == x \in 0..3
=============================================================================
