---- MODULE StringEscape ----
(* "a\qb": SANY's lexer knows only the escapes \" \\ \n \t \r \f, so an   *)
(* unknown one is a lexical error at the q, line 7 column 17 (issue 27     *)
(* item 3), exit 150.                                                      *)
VARIABLE x
Init ==
  x = "a" /\ "a\qb" = x
Next == x' = x
====
