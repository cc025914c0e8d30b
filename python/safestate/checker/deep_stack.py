"""Run the search on a thread with a large stack and a high recursion limit.

Recursive TLA+ operators and functions recurse in Python too (several frames per
level); with Python's default limit of 1000 frames a recursion TLC handles easily
(depth 500) failed.  A recursion too deep even for this limit (TLC's
StackOverflowError) becomes an evaluation error, never a Python traceback.
"""

from __future__ import annotations

import sys
import threading
from typing import Callable, TypeVar

T = TypeVar("T")

RECURSION_LIMIT = 120_000
STACK_BYTES = 512 * 1024 * 1024  # reserved address space; only the pages used are allocated


def stack_overflow_message(doing: str) -> str:
    """TLC's StackOverflowError, in one line."""
    return (f"recursion too deep while {doing} (TLC: StackOverflowError): a recursive operator or "
            f"function probably does not terminate")


def call_with_deep_stack(fn: Callable[[], T]) -> T:
    if threading.current_thread() is not threading.main_thread():
        return fn()
    box: list = []

    def run() -> None:
        try:
            box.append((True, fn()))
        except BaseException as e:  # noqa: BLE001 - re-raised in the caller's thread
            box.append((False, e))
    old_limit, old_size = sys.getrecursionlimit(), threading.stack_size()
    sys.setrecursionlimit(max(old_limit, RECURSION_LIMIT))
    threading.stack_size(STACK_BYTES)
    try:
        t = threading.Thread(target=run, name="safestate-search")
        t.start()
    finally:
        threading.stack_size(old_size)
    t.join()
    sys.setrecursionlimit(old_limit)
    ok, value = box[0]
    if not ok:
        raise value
    return value
