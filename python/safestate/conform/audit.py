"""Transition-table audit: every row of the C++ table is fired by some replayed step,
except the rows the design page (§6, last paragraph) declares unreachable by
construction -- those must never fire.  A row never taken is a failure."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from types import ModuleType

# Design page §6: "K17 after C13; K22 after C13; K23 and K28 after C11/C14".
UNREACHABLE_BY_CONSTRUCTION = ("K17", "K22", "K23", "K28")


@dataclass
class Audit:
    rows_total: int
    rows_taken: list[str]
    rows_unreachable: list[str]        # declared unreachable and indeed never fired
    rows_missing: list[str]            # reachable rows never fired: failure
    unreachable_fired: list[str]       # declared unreachable but fired: failure
    unknown_fired: list[str]           # fired ids that are not in the table: failure

    @property
    def ok(self) -> bool:
        return not (self.rows_missing or self.unreachable_fired or self.unknown_fired)


def audit(core: ModuleType, fired: Counter) -> Audit:
    ids = [r["id"] for r in core.transition_table()]
    taken = [r for r in ids if fired[r] > 0]
    declared = [r for r in ids if r in UNREACHABLE_BY_CONSTRUCTION]
    return Audit(
        rows_total=len(ids),
        rows_taken=taken,
        rows_unreachable=[r for r in declared if fired[r] == 0],
        rows_missing=[r for r in ids if fired[r] == 0 and r not in UNREACHABLE_BY_CONSTRUCTION],
        unreachable_fired=[r for r in declared if fired[r] > 0],
        unknown_fired=sorted(r for r in fired if r not in ids),
    )
