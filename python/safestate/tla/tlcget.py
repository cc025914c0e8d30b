"""TLC!TLCGet and TLC!TLCSet: the model checker's statistics and integer registers.

``TLCGet("level")`` is the BFS level of the state being evaluated (0 while Init and
the ASSUMEs are evaluated, the predecessor's level in Next, the successor's level
in its constraints and invariants); ``"distinct"``, ``"queue"``, ``"diameter"``,
``"generated"``, ``"duration"`` and ``"stats"`` (a record of all of them) are the
search's counters as TLC reports them at that moment (checked against TLC 1.8.0
with one worker).  ``TLCSet(i, v)`` / ``TLCGet(i)`` store and read register i.

The explorer keeps `RUNTIME` up to date, but only for models that use these
operators (`RUNTIME.used`), so other models pay nothing.
"""

from __future__ import annotations

import time
from typing import Protocol

from .errors import EvalError
from .values import Value, fmt, make_fn


class SearchCounters(Protocol):
    """What the explorer exposes (see `checker/explore.py`)."""

    generated: int
    max_level: int
    head: int
    states: list


class TlcRuntime:
    def __init__(self) -> None:
        self.used = False
        self.reset()

    def reset(self) -> None:
        self.level = 0
        self.search: SearchCounters | None = None
        # 1 while a state is being expanded (TLC has dequeued it).
        self.expanding = 0
        # 1 while the invariants of a new successor are checked (TLC enqueues it after).
        self.pending = 0
        self.start = time.monotonic()
        self.registers: dict[int, Value] = {}

    def stats(self) -> dict[str, int]:
        s = self.search
        if s is None:
            return {"distinct": 0, "queue": 0, "diameter": 1, "generated": 0, "initial": 0,
                    "duration": int(time.monotonic() - self.start), "worker": 0}
        return {"distinct": len(s.states), "queue": len(s.states) - s.head - self.expanding - self.pending,
                "diameter": max(s.max_level, 1), "generated": s.generated,
                "initial": len(getattr(s, "initial", ())), "duration": int(time.monotonic() - self.start),
                "worker": 0}


RUNTIME = TlcRuntime()


def tlc_get(key: Value) -> Value:
    if type(key) is int:
        if key not in RUNTIME.registers:
            raise EvalError(f"TLCGet({key}) was called, but register {key} has not been set by TLCSet")
        return RUNTIME.registers[key]
    if key == "level":
        return RUNTIME.level
    if key == "stats":
        return make_fn(dict(RUNTIME.stats()))
    stats = RUNTIME.stats()
    if type(key) is str and key in stats:
        return stats[key]
    raise EvalError(f"TLCGet({fmt(key)}) is not supported: the argument must be an integer register or one "
                    f"of \"level\", \"distinct\", \"queue\", \"diameter\", \"generated\", \"duration\", "
                    f"\"stats\"")


def tlc_set(key: Value, value: Value) -> bool:
    if type(key) is not int or key < 0:
        raise EvalError(f"TLCSet({fmt(key)}, ...) is not supported: the first argument must be a natural "
                        f"number (an integer register)")
    RUNTIME.registers[key] = value
    return True
