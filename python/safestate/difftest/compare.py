"""Comparing our summary with TLC's."""

from __future__ import annotations

from ..checker.tlc import TlcSummary
from .ours import REFUSED

FIELDS = ("result", "violated", "distinct_states", "states_generated", "depth", "exit_code")


def differences(ours: dict, tlc: TlcSummary) -> list[str]:
    """Fields on which we differ from TLC.  A refusal (an unsupported construct,
    reported as such) is not a difference; counts TLC did not print are skipped."""
    if ours.get("result") == REFUSED:
        return []
    diffs = []
    for name in FIELDS:
        theirs = getattr(tlc, name)
        if theirs is None and name in ("distinct_states", "states_generated", "depth"):
            continue
        if ours.get(name) != theirs:
            diffs.append(name)
    return diffs


def describe(ours: dict, tlc: TlcSummary, diffs: list[str]) -> str:
    return "; ".join(f"{d}: ours {ours.get(d)!r}, TLC {getattr(tlc, d)!r}" for d in diffs)
