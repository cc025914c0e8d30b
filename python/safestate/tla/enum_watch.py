"""A watch over long enumerations: the memory limit and progress lines while a big
set is enumerated (``Init == x \\in SUBSET (1..40)`` materialises 2^40 sets before
the first state exists, so the search's own per-state checks never run).

The checker arms `ENUM_WATCH` for the duration of a search; `watched(it, what)`
wraps the iterator of a set being materialised and, every `CHECK_EVERY` elements,
raises `MemoryLimitExceeded` above the limit and reports progress every
`PROGRESS_SECONDS`.  Disarmed (the default) it costs one attribute test per set.
"""

from __future__ import annotations

import os
import time
from typing import Callable, Iterable, Iterator, TypeVar

T = TypeVar("T")

CHECK_EVERY = 1 << 15
PROGRESS_SECONDS = 5.0


class MemoryLimitExceeded(Exception):
    """The resident memory went above the limit; `where` says what was being computed."""

    def __init__(self, where: str = "") -> None:
        super().__init__(where)
        self.where = where


def rss_mb() -> float:
    """This process's resident memory in MB (0 where /proc is missing)."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2 ** 20
    except OSError:
        return 0.0


class EnumWatch:
    def __init__(self) -> None:
        self.limit_mb: float | None = None
        self.progress: Callable[[str], None] | None = None
        self.last_progress = 0.0

    def arm(self, limit_mb: float, progress: Callable[[str], None] | None) -> None:
        self.limit_mb, self.progress = limit_mb, progress
        self.last_progress = time.monotonic()

    def disarm(self) -> None:
        self.limit_mb = self.progress = None

    def check(self, what: str, count: int) -> None:
        """The memory limit and a progress line; `count` elements of `what` so far."""
        if self.limit_mb is None:
            return
        if rss_mb() > self.limit_mb:
            raise MemoryLimitExceeded(f"enumerating {what}: {count} elements so far")
        now = time.monotonic()
        if self.progress is not None and now - self.last_progress >= PROGRESS_SECONDS:
            self.last_progress = now
            self.progress(f"Enumerating {what}: {count} elements so far, {rss_mb():.0f} MB in use.")

    def watched(self, items: Iterable[T], describe: Callable[[], str]) -> Iterator[T]:
        """`items`, checked every CHECK_EVERY elements while the watch is armed."""
        if self.limit_mb is None:
            yield from items
            return
        n = 0
        for x in items:
            n += 1
            if n % CHECK_EVERY == 0:
                self.check(describe(), n)
            yield x


ENUM_WATCH = EnumWatch()
