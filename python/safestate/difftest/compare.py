"""Comparing our summary with TLC's."""

from __future__ import annotations

import re

from ..checker.tlc import TlcSummary
from .ours import REFUSED

FIELDS = ("result", "violated", "distinct_states", "states_generated", "depth", "exit_code")


def differences(ours: dict, tlc: TlcSummary, states_comparable: bool = True) -> list[str]:
    """Fields on which we differ from TLC.  A refusal (an unsupported construct,
    reported as such) is not a difference; counts TLC did not print are skipped.
    The length of a safety/deadlock trace is always compared, its states only when
    `states_comparable` (with SYMMETRY or VIEW TLC may print another member of a
    state's class)."""
    if ours.get("result") == REFUSED:
        return []
    diffs = []
    for name in FIELDS:
        theirs = getattr(tlc, name)
        if theirs is None and name in ("distinct_states", "states_generated", "depth"):
            continue
        if ours.get(name) != theirs:
            diffs.append(name)
    mine, theirs = ours.get("trace"), tlc.trace
    if theirs is not None and (mine is None or len(mine) != len(theirs)):
        diffs.append("trace_length")
    elif theirs is not None and mine is not None and states_comparable and [_words(x) for x in mine] != [_words(x) for x in theirs]:
        diffs.append("trace_states")
    return diffs


def states_comparable(cfg: str) -> bool:
    return re.search(r"^\s*(SYMMETRY|VIEW)\b", cfg, re.M) is None


def _words(state: str) -> list[str]:
    """A state's conjuncts `/\\ v = value`, without line breaks (TLC wraps long
    values), sorted: TLC prints the variables in the order of SANY's hash table
    (e.g. JugPuzzle's `small` before `big`), we in declaration order; the
    state is the same."""
    text = " ".join(state.split())
    return sorted(part.strip() for part in re.split(r"(?:^| )/\\ ", text) if part.strip())


def describe(ours: dict, tlc: TlcSummary, diffs: list[str]) -> str:
    def field(d: str) -> str:
        if d.startswith("trace"):
            return f"{d}: ours {ours.get('trace')!r}, TLC {tlc.trace!r}"
        return f"{d}: ours {ours.get(d)!r}, TLC {getattr(tlc, d)!r}"
    return "; ".join(field(d) for d in diffs)
