"""Issue 32: the native core takes \\A over an action whose body branches (TLC's
conjunction of one instance per binding, the lamport_mutex case), and SUBSET, \\X and
[S -> T] both as values (enumerated in TLC's order) and in membership tests; the
Python engine's verdict, counts, depth, states left and trace are the reference."""

from __future__ import annotations

from pathlib import Path

import pytest

from native_engines import assert_cli_engines_agree, assert_engines_agree, write_spec
from safestate.checker.model import load_model
from safestate.checker.native.search import native_unsupported

CFG = "INIT Init\nNEXT Next\nINVARIANT Inv\n"

# Each instance of the \A may assign a variable another instance assigned: the
# conjunction holds only where they agree; a later instance, once every variable is
# assigned, is a boolean (TLC's getNextStatesAllAssigned).
FORALL_SPECS = {
    "beats": r"""EXTENDS Naturals
VARIABLES req, crit
Beats(p, q) == \/ req[q] = 0
               \/ req[p] < req[q]
               \/ req[p] = req[q] /\ p < q
Init == req = [p \in 1..3 |-> 0] /\ crit = {}
Request(p) == req[p] = 0 /\ req' = [req EXCEPT ![p] = 1 + (p % 2)] /\ UNCHANGED crit
Enter(p) == /\ req[p] > 0 /\ p \notin crit
            /\ \A q \in {1, 2, 3} \ {p} : Beats(p, q)
            /\ crit' = crit \cup {p} /\ UNCHANGED req
Exit(p) == p \in crit /\ crit' = crit \ {p} /\ req' = [req EXCEPT ![p] = 0]
Next == \E p \in 1..3 : Request(p) \/ Enter(p) \/ Exit(p)
Inv == crit # {1, 2, 3}
""",
    "assigning instances": r"""EXTENDS Naturals
VARIABLES x, y
Init == x = 0 /\ y = 0
Next == /\ \A i \in {1, 2} : \/ x' = (x + 1) % 4
                             \/ y' = (y + i) % 3
        /\ x' \in 0..3
        /\ y' \in 0..2
Inv == x + y < 5
""",
    "two binders and a LET": r"""EXTENDS Naturals
VARIABLES x, y
Init == x = 0 /\ y = 1
Next == /\ \A i \in {0, 1}, j \in {2} : LET d == i + j IN \/ x' = (x + d) % 5
                                                        \/ y' = (y * d) % 7
        /\ x' \in 0..4
        /\ y' \in 0..6
Inv == y # 6
""",
}


@pytest.mark.parametrize("name", sorted(FORALL_SPECS))
def test_forall_over_a_branching_action_gives_the_python_engines_result(name: str, tmp_path: Path) -> None:
    tla = write_spec(tmp_path, "Forall", FORALL_SPECS[name], CFG)
    r = assert_engines_agree(tla)
    assert r.distinct_states > 1 and r.result == "safety failure"
    assert_engines_agree(tla, workers=2)


def test_forall_over_a_branching_action_cli_reports_what_the_python_engine_reports(tmp_path: Path) -> None:
    tla = write_spec(tmp_path, "Forall", FORALL_SPECS["two binders and a LET"], CFG)
    assert assert_cli_engines_agree(tla) == 12  # y reaches 6: the invariant is violated


SET_SPECS = {
    "SUBSET as a value and in a test": r"""EXTENDS Naturals
VARIABLES s, n
Size(S) == IF S = {} THEN 0 ELSE IF \E a \in S : S = {a} THEN 1 ELSE 2
Init == s = {} /\ n = 0
Next == /\ n < 3 /\ n' = n + 1
        /\ \E t \in SUBSET {1, 2, 3} : Size(t) = n' /\ s' = t
Inv == s \in SUBSET (1..3) /\ {s} \in SUBSET SUBSET {1, 2, 3} /\ s # {1, 3}
""",
    "\\X as a value and in a test": r"""EXTENDS Naturals
VARIABLES p
Init == p = <<0, "a">>
Next == \E q \in ({1, 2} \X {"a", "b"}) \X {TRUE} : p' = q[1] /\ p \in (0..2) \X {"a", "b"}
Inv == p \in {1, 2} \X {"a", "b"} => p # <<2, "b">>
""",
    "[S -> T] as a value and in a test": r"""EXTENDS Naturals
VARIABLES f, k
Init == f = [i \in {10, 20} |-> 0] /\ k = 0
Next == /\ k < 9 /\ k' = k + 1
        /\ \E g \in [{10, 20} -> 0..2] : g[10] + g[20] = k' % 4 /\ f' = g
        /\ f \in [{10, 20} -> Nat]
Inv == \A g \in [1..2 -> {f[10]}] : g # <<2, 2>>
""",
}


@pytest.mark.parametrize("name", sorted(SET_SPECS))
def test_structured_sets_give_the_python_engines_result(name: str, tmp_path: Path) -> None:
    tla = write_spec(tmp_path, "Sets", SET_SPECS[name], CFG)
    r = assert_engines_agree(tla)
    assert r.result == "safety failure" and r.trace is not None and len(r.trace) > 1
    assert_engines_agree(tla, workers=2)
    assert assert_cli_engines_agree(tla) == 12


def test_tostring_of_a_structured_set_is_left_to_the_python_engine(tmp_path: Path) -> None:
    # TLC prints SUBSET {1, 2} as written, the core holds it by its elements.
    tla = write_spec(tmp_path, "Printed", "EXTENDS Naturals, TLC\nVARIABLE s\nInit == s = \"\"\n"
                     "Next == s' = ToString(SUBSET {1, 2})\nInv == TRUE\n", CFG)
    refusal = native_unsupported(load_model(tla))
    assert refusal is not None and "ToString" in refusal.message and refusal.loc is not None
    assert refusal.loc.line == 5
