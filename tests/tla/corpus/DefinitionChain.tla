---- MODULE DefinitionChain ----
(***************************************************************************)
(* A chain of 100 definitions D_i == D_(i-1) + 1, used in Init and under a *)
(* prime in Next, where both engines expand it at the call site (issue 27   *)
(* item 4: it was refused past 60 as a "recursive action-level operator"). *)
(* TLC: no error, 4 states generated, 3 distinct, depth 3.                  *)
(***************************************************************************)
EXTENDS Naturals
VARIABLE x
D0 == x
D1 == D0 + 1
D2 == D1 + 1
D3 == D2 + 1
D4 == D3 + 1
D5 == D4 + 1
D6 == D5 + 1
D7 == D6 + 1
D8 == D7 + 1
D9 == D8 + 1
D10 == D9 + 1
D11 == D10 + 1
D12 == D11 + 1
D13 == D12 + 1
D14 == D13 + 1
D15 == D14 + 1
D16 == D15 + 1
D17 == D16 + 1
D18 == D17 + 1
D19 == D18 + 1
D20 == D19 + 1
D21 == D20 + 1
D22 == D21 + 1
D23 == D22 + 1
D24 == D23 + 1
D25 == D24 + 1
D26 == D25 + 1
D27 == D26 + 1
D28 == D27 + 1
D29 == D28 + 1
D30 == D29 + 1
D31 == D30 + 1
D32 == D31 + 1
D33 == D32 + 1
D34 == D33 + 1
D35 == D34 + 1
D36 == D35 + 1
D37 == D36 + 1
D38 == D37 + 1
D39 == D38 + 1
D40 == D39 + 1
D41 == D40 + 1
D42 == D41 + 1
D43 == D42 + 1
D44 == D43 + 1
D45 == D44 + 1
D46 == D45 + 1
D47 == D46 + 1
D48 == D47 + 1
D49 == D48 + 1
D50 == D49 + 1
D51 == D50 + 1
D52 == D51 + 1
D53 == D52 + 1
D54 == D53 + 1
D55 == D54 + 1
D56 == D55 + 1
D57 == D56 + 1
D58 == D57 + 1
D59 == D58 + 1
D60 == D59 + 1
D61 == D60 + 1
D62 == D61 + 1
D63 == D62 + 1
D64 == D63 + 1
D65 == D64 + 1
D66 == D65 + 1
D67 == D66 + 1
D68 == D67 + 1
D69 == D68 + 1
D70 == D69 + 1
D71 == D70 + 1
D72 == D71 + 1
D73 == D72 + 1
D74 == D73 + 1
D75 == D74 + 1
D76 == D75 + 1
D77 == D76 + 1
D78 == D77 + 1
D79 == D78 + 1
D80 == D79 + 1
D81 == D80 + 1
D82 == D81 + 1
D83 == D82 + 1
D84 == D83 + 1
D85 == D84 + 1
D86 == D85 + 1
D87 == D86 + 1
D88 == D87 + 1
D89 == D88 + 1
D90 == D89 + 1
D91 == D90 + 1
D92 == D91 + 1
D93 == D92 + 1
D94 == D93 + 1
D95 == D94 + 1
D96 == D95 + 1
D97 == D96 + 1
D98 == D97 + 1
D99 == D98 + 1
D100 == D99 + 1
Init == x = 0 /\ D100 = 100
Next == x' = (x + 1) % 3 /\ D100' = x' + 100
====
