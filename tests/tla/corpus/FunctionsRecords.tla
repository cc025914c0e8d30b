-------------------------- MODULE FunctionsRecords --------------------------
(***************************************************************************)
(* A tiny spreadsheet: a 2 x 2 grid of cells, each a record holding a      *)
(* value in 0..1 and a "locked" flag, plus an audit record of the last     *)
(* edit.  Edits bump a value, lock or unlock a cell, or clear a whole row. *)
(*                                                                         *)
(* Exercises: [x \in S |-> e], [S -> T], DOMAIN, records [a |-> 1],        *)
(* record sets [a : S, b : T], .field access, EXCEPT with @, nested paths  *)
(* ![i][j] and ![i][j].f, several updates in one EXCEPT, tuples,           *)
(* function equality, :> and @@ from TLC.  Expected: success.              *)
(***************************************************************************)
EXTENDS Naturals, TLC

Rows == {1, 2}
Cols == {"x", "y"}

Cell == [val : 0..1, locked : BOOLEAN]

VARIABLES grid, last

Init ==
    /\ grid = [r \in Rows |-> [c \in Cols |-> [val |-> 0, locked |-> FALSE]]]
    /\ last = [op |-> "none", at |-> <<1, "x">>]

Bump(r, c) ==
    /\ ~grid[r][c].locked
    /\ grid[r][c].val < 1
    /\ grid' = [grid EXCEPT ![r][c].val = @ + 1]
    /\ last' = [last EXCEPT !.op = "bump", !.at = <<r, c>>]

Toggle(r, c) ==
    /\ grid' = [grid EXCEPT ![r][c] = [@ EXCEPT !.locked = ~@]]
    /\ last' = [op |-> "toggle", at |-> <<r, c>>]

\* Clear every unlocked cell of row r, in one multi-path EXCEPT.
ClearRow(r) ==
    /\ \E c \in Cols : grid[r][c].val > 0
    /\ grid' = [grid EXCEPT
                  ![r]["x"].val = IF grid[r]["x"].locked THEN @ ELSE 0,
                  ![r]["y"].val = IF grid[r]["y"].locked THEN @ ELSE 0]
    /\ last' = [last EXCEPT !.op = "clear", !.at[1] = r]

Next ==
    \/ \E r \in Rows, c \in Cols : Bump(r, c) \/ Toggle(r, c)
    \/ \E r \in Rows : ClearRow(r)

TypeOK ==
    /\ grid \in [Rows -> [Cols -> Cell]]
    /\ last \in [op : {"none", "bump", "toggle", "clear"}, at : Rows \X Cols]

Shape ==
    /\ DOMAIN grid = Rows
    /\ \A r \in Rows : DOMAIN grid[r] = Cols
    /\ DOMAIN last = {"op", "at"}
    /\ last.at[2] \in Cols
    /\ (1 :> "a" @@ 2 :> "b") = [i \in 1..2 |-> IF i = 1 THEN "a" ELSE "b"]
    /\ (1 :> "a" @@ 1 :> "b")[1] = "a"
    /\ [grid EXCEPT ![1] = grid[1]] = grid
    /\ <<last.op, 7>>[2] = 7

\* The sum of all values, via a LET-local operator with two parameters.
Total == LET v(r, c) == grid[r][c].val
         IN  v(1, "x") + v(1, "y") + v(2, "x") + v(2, "y")
Bounded == Total <= 4
=============================================================================
