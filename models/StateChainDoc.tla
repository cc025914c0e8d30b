---------------------------- MODULE StateChainDoc ----------------------------
(* StateChain on the tree of the seed document's Figure 4 / StBuild():      *)
(* S0 -> {S1 (parallel), S2}; S1 -> sub-chains SA {S3, S4 (parallel)} and   *)
(* SB {S5, S6}; S4 -> sub-chains SY {S7} and SZ {S8}.                        *)
EXTENDS StateChain

DocOrder == <<"S0", "S1", "SA", "S3", "S4", "SY", "S7", "SZ", "S8", "SB", "S5", "S6", "S2">>
DocParent ==
    [s \in {DocOrder[i] : i \in 1..Len(DocOrder)} |->
        CASE s = "S0" -> "none"
          [] s \in {"S1", "S2"} -> "S0"
          [] s \in {"SA", "SB"} -> "S1"
          [] s \in {"S3", "S4"} -> "SA"
          [] s \in {"S5", "S6"} -> "SB"
          [] s \in {"SY", "SZ"} -> "S4"
          [] s = "S7" -> "SY"
          [] s = "S8" -> "SZ"]
DocInitial ==
    [s \in {DocOrder[i] : i \in 1..Len(DocOrder)} |->
        CASE s = "S0" -> "S1"
          [] s = "SA" -> "S3"
          [] s = "SB" -> "S5"
          [] s = "SY" -> "S7"
          [] s = "SZ" -> "S8"
          [] OTHER -> "none"]
DocParallel == {"S1", "S4"}
===============================================================================
