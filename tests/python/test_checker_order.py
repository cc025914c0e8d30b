"""TLC's enumeration order decides the counts at the moment a violation is found.

The expected numbers below were obtained by running TLC 1.8.0
(`java -cp tla2tools.jar tlc2.TLC -workers 1`) on these very specs.

* `\\E a \\in A, b \\in B : ...` in an action: TLC (ContextEnumerator) evaluates all bound
  sets, then turns the FIRST binder fastest: (a1, b1), (a2, b1), ..., (a1, b2), ...
* Strings are ordered by when TLC interned them: first the words of every parsed file
  (the spec, then its EXTENDS, then its INSTANCEs, standard modules included), then the
  contents of string literals, module by module in semantic-analysis order.
* "states left on queue": the state being expanded has been dequeued, and a new
  successor violating an invariant is never enqueued.

The checks run in a subprocess so that the string order (interned per process, as in
TLC) is not influenced by other tests.
"""

from __future__ import annotations

import json

import pytest

from conftest import run_safestate

ORDER2 = """---- MODULE Order2 ----
VARIABLES x, d, z
Init == x \\in {"a", "b"} /\\ d = "none" /\\ z = TRUE
Next == \\E e \\in {"p", "q", "r"}, y \\in BOOLEAN : x' = x /\\ d' = e /\\ z' = y
Inv == ~(x = "a" /\\ d = "r" /\\ z = FALSE)
====
"""

ORDER3 = """---- MODULE Order3 ----
VARIABLES x, d, z
Init == x \\in {"a", "b"} /\\ d = <<0, 0>> /\\ z = TRUE
Next == \\E <<u, v>> \\in {<<1, 2>>, <<3, 4>>}, e \\in {"p", "q"}, y \\in BOOLEAN :
          x' = e /\\ d' = <<u, v>> /\\ z' = y
Inv == ~(x = "q" /\\ d = <<3, 4>> /\\ z = FALSE)
====
"""

DEAD = """---- MODULE Dead ----
VARIABLES x
Init == x \\in {"a", "b", "c"}
Next == x # "b" /\\ x' = "d"
====
"""

# "yy" is a word (interned while parsing), so it precedes "zz", although "zz" comes
# first in the text; "a" and "b" are words of Naturals.
INTERN = """---- MODULE Intern ----
EXTENDS Naturals
VARIABLES x, n
Init == x \\in {"zz", "b", "yy", "Len", "a"} /\\ n = 0
yy == 1
Next == n < 2 /\\ n' = n + 1 /\\ x' = x
Inv == ~(x = "zz" /\\ n = 1)
====
"""

# TLC.tla (extended) is parsed before Naturals (extended too), then Sequences and
# FiniteSets (instantiated by TLC.tla).
INTERN2 = INTERN.replace("MODULE Intern ", "MODULE Intern2 ").replace(
    "EXTENDS Naturals", "EXTENDS TLC, Naturals").replace(
    '"a"}', '"a", "seq", "CS", "Print", "Test"}')

INV_CFG = "INIT Init\nNEXT Next\nINVARIANT Inv\n"


@pytest.mark.parametrize("name, tla, cfg, want", [
    # TLC 1.8.0: 5 states generated, 5 distinct states found, 3 states left on queue.
    # (Binder order e-outer would give 7 / 7.)
    ("Order2", ORDER2, INV_CFG, ("safety failure", 5, 5, 3, 2,
                                 {"e": "r", "y": False})),
    # TLC 1.8.0: 6 states generated, 6 distinct states found, 4 states left on queue.
    ("Order3", ORDER3, INV_CFG, ("safety failure", 6, 6, 4, 2,
                                 {"u": {"#bigint": "3"}, "v": {"#bigint": "4"}, "e": "q", "y": False})),
    # TLC 1.8.0: Deadlock reached. 4 states generated, 4 distinct states found,
    # 2 states left on queue.
    # TLC 1.8.0: initial states in the order "yy", "a", "b", "zz", "Len";
    # 9 states generated, 9 distinct states found, 4 states left on queue.
    ("Intern", INTERN, INV_CFG, ("safety failure", 9, 9, 4, 2, {})),
    # TLC 1.8.0: initial states in the order "yy", "Print", "Len", "a", "b", "Test", "seq",
    # "CS", "zz"; 18 states generated, 18 distinct states found, 8 states left on queue.
    ("Intern2", INTERN2, INV_CFG, ("safety failure", 18, 18, 8, 2, {})),
    ("Dead", DEAD, "INIT Init\nNEXT Next\n", ("deadlock failure", 4, 4, 2, 1, None)),
])
def test_checker_counts_at_violation_follow_tlc_enumeration_order(tla_dir, name, tla, cfg, want) -> None:
    path = tla_dir(name, tla, cfg)
    proc = run_safestate("check", str(path), "--json", "--workers", "1")
    got = json.loads(proc.stdout)
    result, generated, distinct, left, trace_len, params = want
    assert (got["result"], got["states_generated"], got["distinct_states"], got["left_on_queue"]) == (
        result, generated, distinct, left)
    states = got["trace"]["states"]
    assert len(states) == trace_len
    assert states[0]["x"] == {"Dead": "b", "Intern": "zz", "Intern2": "zz"}.get(name, "a")
    if params is not None:
        assert states[-1]["#meta"]["params"] == params


def test_checker_expression_quantifier_turns_first_binder_fastest(tla_dir) -> None:
    # TLC 1.8.0 prints <<1, "v">>, <<2, "v">>, <<1, "u">>, <<2, "u">> for Inv ("v" is a
    # word of TLC.tla, so it precedes "u"), then the same four lines for Inv2, whose
    # witness is the last one.
    path = tla_dir("Quant", """---- MODULE Quant ----
EXTENDS TLC
VARIABLE x
Init == x = 0
Next == UNCHANGED x
Inv == \\A a \\in {1, 2}, b \\in {"u", "v"} : PrintT(<<a, b>>)
Inv2 == \\E a \\in {1, 2}, b \\in {"u", "v"} : PrintT(<<a, b>>) /\\ a = 2 /\\ b = "u"
====
""", "INIT Init\nNEXT Next\nINVARIANT Inv\nINVARIANT Inv2\n")
    proc = run_safestate("check", str(path), "--workers", "1")
    printed = [line for line in (proc.stdout + proc.stderr).splitlines() if line.startswith("<<")]
    four = ['<<1, "v">>', '<<2, "v">>', '<<1, "u">>', '<<2, "u">>']
    assert printed[:8] == four + four
