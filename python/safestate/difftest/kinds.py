"""Grammar 6: values of mixed kinds (issue 27 item 1), where Python's ``True == 1``
could make two TLA+ values one.

Each spec has a counter ``n`` and one to three variables that take values from
`POOL`: integers and booleans, and sets, sequences, records and functions holding
one or the other (``{0}`` and ``{FALSE}``, ``<<1, FALSE>>`` and ``<<TRUE, 0>>``,
``[val |-> 0]`` and ``[val |-> FALSE]``, ``[b \\in BOOLEAN |-> 0]`` and ``[i \\in 0..1
|-> 0]``).  Invariants compare printed forms (``ToString(x) # ToString(<<1>>)``, legal
for every kind); now and then an action or an invariant compares values directly
(``x = 1``, ``x \\in BOOLEAN``, ``{x, y}``), which TLC refuses with an error when the
kinds differ: both the counts and the errors are compared.
"""

from __future__ import annotations

import random

from .generator import GeneratedSpec

POOL = [
    "0", "1", "TRUE", "FALSE", "2",
    "{0}", "{FALSE}", "{1, 2}", "{TRUE, FALSE}", "{}", "{0, 1}",
    "<<1, FALSE>>", "<<TRUE, 0>>", "<<1>>", "<<TRUE>>", "<<>>", "<<0, 1>>", "<<FALSE, TRUE>>",
    "[val |-> 0]", "[val |-> FALSE]", "[val |-> TRUE]", "[val |-> 1]", "[val |-> <<0>>]", "[val |-> <<FALSE>>]",
    "[b \\in BOOLEAN |-> 0]", "[i \\in 0..1 |-> 0]", "[i \\in 0..1 |-> TRUE]", "(FALSE :> 1)", "(0 :> 1)",
    "{<<1>>}", "{<<TRUE>>}", "{[val |-> 0]}", "{[val |-> FALSE]}", "{{0}}", "{{FALSE}}",
]
# Comparisons TLC makes (an error when the kinds differ).
DIRECT = ["{x} = {0}", "{x} # {FALSE}", "x \\in BOOLEAN", "x \\notin {0, 1}", "x = <<TRUE>>", "x # [val |-> 0]"]


def generate_kinds(seed: int, index: int) -> GeneratedSpec:
    """Spec number `index` of the run seeded with `seed` (reproducible on its own)."""
    rng = random.Random(f"kinds:{seed}:{index}")
    name = f"K{seed}x{index}"
    nvars = rng.randint(1, 3)
    vs = [f"x{i}" for i in range(nvars)]
    bound = rng.randint(2, 4)
    lines = [f"---- MODULE {name} ----", "EXTENDS Naturals, Sequences, FiniteSets, TLC",
             f"VARIABLES n, {', '.join(vs)}"]
    direct = rng.random() < 0.3  # comparisons that may be errors

    def pick() -> str:
        return rng.choice(POOL)

    def choice_of(v: str) -> str:
        k = rng.randint(0, 4)
        if k == 0:
            return f"{v}' = {pick()}"
        if k == 1:
            return f"({v}' = {pick()} \\/ {v}' = {pick()})"
        if k == 2:
            return f"(IF n % 2 = 0 THEN {v}' = {pick()} ELSE {v}' = {pick()})"
        if k == 3:
            return f"\\E w \\in {{{rng.randint(0, 1)}, 2}} : {v}' = IF w = 2 THEN {pick()} ELSE {pick()}"
        return f"{v}' = {v}"

    init = ["/\\ n = 0"] + [f"/\\ {v} = {pick()}" for v in vs]
    lines += ["Init =="] + ["    " + c for c in init]
    actions = []
    for a in range(rng.randint(1, 3)):
        body = [f"/\\ n' = (n + 1) % {bound}"] + [f"/\\ {choice_of(v)}" for v in vs]
        if direct and rng.random() < 0.3:
            body.append(f"/\\ {rng.choice(DIRECT).replace('x', rng.choice(vs))}")
        if nvars > 1 and direct and rng.random() < 0.2:
            body.append(f"/\\ Cardinality({{{', '.join(vs)}}}) > 0")
        lines.append(f"A{a} ==")
        lines += ["    " + c for c in body]
        actions.append(f"A{a}")
    lines.append("Next ==")
    lines += [f"    \\/ {a}" for a in actions]
    invs = []
    for i in range(rng.randint(0, 2)):
        v = rng.choice(vs)
        if direct and rng.random() < 0.4:
            inv = rng.choice(DIRECT).replace("x", v)
        else:
            inv = f"ToString({v}) # ToString({pick()})"
        lines.append(f"Inv{i} == {inv}")
        invs.append(f"Inv{i}")
    lines.append("====")
    cfg = ["INIT Init", "NEXT Next"] + [f"INVARIANT {i}" for i in invs]
    return GeneratedSpec(name, "\n".join(lines) + "\n", "\n".join(cfg) + "\n", ("mixed_kinds",))
