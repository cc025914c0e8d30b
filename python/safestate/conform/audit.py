"""Transition-table audit: every row of the C++ table is fired by some replayed step,
except the rows the design page declares unreachable by construction (the adapter's
`unreachable_rows`) -- those must never fire.  A row never taken is a failure."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from .adapter import Adapter


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


def audit(adapter: Adapter, fired: Counter) -> Audit:
    ids = adapter.table_rows()
    unreachable = adapter.unreachable_rows
    taken = [r for r in ids if fired[r] > 0]
    declared = [r for r in ids if r in unreachable]
    return Audit(
        rows_total=len(ids),
        rows_taken=taken,
        rows_unreachable=[r for r in declared if fired[r] == 0],
        rows_missing=[r for r in ids if fired[r] == 0 and r not in unreachable],
        unreachable_fired=[r for r in declared if fired[r] > 0],
        unknown_fired=sorted(r for r in fired if r not in ids),
    )
